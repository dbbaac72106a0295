"""The Blender add-on, end to end in a headless Blender:

    blender -b --factory-startup --python-exit-code 1 --python tests/clients/blender_addon_test.py -- [Geno.fbx]

Imports a character (the corpus' Geno.fbx through Blender's FBX importer, or when that file is
absent the shipped Unreal-named rig fixtures/rigs/unreal_quaternius.bvh through the BVH
importer), keys its hips (rotation + location) and legs every 8 frames over 3 s of a real walk
(the first 3 s of fixtures/sketches/walk_proud_002_legs8.glb, a style the default database
lacks, retargeted onto the imported armature by mocapfill), runs
bpy.ops.mocapfill.fill_action(method='hierarchical') and checks the new action. Everything is
measured through Blender's own evaluation (frame_set, pose matrices), not the add-on's math.
Exit code 0 on success, 1 on any failure.
"""
import math
import os
import sys
import time
import traceback

import bpy
import addon_utils

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.path.normpath(os.path.join(HERE, "..", ".."))
FIXTURES = os.path.join(SOURCE, "fixtures")
WALK = os.path.join(FIXTURES, "sketches", "walk_proud_002_legs8.glb")
FALLBACK_RIG = os.path.join(FIXTURES, "rigs", "unreal_quaternius.bvh")

FPS = 30
KEY_STEP = 8  # frames between the sketch's keys
SECONDS = 3.0
FIRST_FRAME = 1
KEY_TOLERANCE_DEG = 0.01
LOCATION_TOLERANCE_M = 1e-4
MOVES_DEG = 2.0  # a synthesised bone must turn at least this much over the clip

# Per rig: the bones the animator keys (hips, then the legs; a root bone above the hips too, since
# mocapfill's retarget moves the character with it), those also keyed in location, and bones that
# must be synthesised.
RIGS = {
    "geno": {"keyed": ["Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "RightUpLeg", "RightLeg", "RightFoot"],
             "located": ["Hips"],
             "synthesised": ["Spine1", "Neck", "LeftArm", "LeftForeArm", "RightArm", "RightForeArm"]},
    "unreal": {"keyed": ["root", "pelvis", "thigh_l", "calf_l", "foot_l", "thigh_r", "calf_r", "foot_r"],
               "located": ["root", "pelvis"],
               "synthesised": ["spine_02", "neck_01", "upperarm_l", "lowerarm_l", "upperarm_r", "lowerarm_r"]},
}


class TestFailure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise TestFailure(message)


def arguments():
    """[Geno.fbx] [--coverage blend|warn] after Blender's "--"."""
    import argparse
    parser = argparse.ArgumentParser(prog="blender_addon_test.py")
    parser.add_argument("geno", nargs="?", default="", help="the corpus' Geno.fbx (a fixture rig when absent)")
    parser.add_argument("--coverage", default="blend", choices=["blend", "warn"],
                        help="the operator's coverage option (default: the operator's default, blend)")
    return parser.parse_args(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else [])


def enable_addon():
    sys.path.insert(0, os.path.join(SOURCE, "blender"))
    module = addon_utils.enable("mocapfill_blender", default_set=True, handle_error=None)
    check(module is not None, "addon_utils.enable('mocapfill_blender') failed")
    check(hasattr(bpy.ops.mocapfill, "fill_action"), "bpy.ops.mocapfill.fill_action is not registered")
    return module


def import_bvh(path, **options):
    """Blender 3.4's BVH importer opens files with mode 'rU', which Python 3.11 (Debian's Blender
    runs on it) refuses ("invalid mode: 'rU'"); the importer module is given an open() that
    drops the 'U'."""
    import builtins
    from io_anim_bvh import import_bvh as importer
    importer.open = lambda file, mode="r", *args, **kwargs: builtins.open(file, mode.replace("U", ""), *args, **kwargs)
    return bpy.ops.import_anim.bvh(filepath=path, **options)


def disconnect(armature, names):
    """Blender ignores the location of a bone connected to its parent (the BVH importer connects
    the Unreal rig's pelvis to its root bone): an animator keying the hips' travel disconnects them."""
    if not any(armature.data.bones[n].use_connect for n in names):
        return
    bpy.ops.object.mode_set(mode='EDIT')
    for name in names:
        armature.data.edit_bones[name].use_connect = False
    bpy.ops.object.mode_set(mode='OBJECT')


def import_character(geno_path):
    """The armature object and the rig's bone table."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    enable_addon()  # read_factory_settings drops add-ons enabled before it
    if geno_path and os.path.exists(geno_path):
        bpy.ops.import_scene.fbx(filepath=geno_path)
        kind, source = "geno", geno_path
    else:
        # The fixture is in centimetres: 0.01 gives Blender a character in metres, as an animator's.
        import_bvh(FALLBACK_RIG, global_scale=0.01)
        kind, source = "unreal", FALLBACK_RIG
    armatures = [o for o in bpy.context.scene.objects if o.type == 'ARMATURE']
    check(len(armatures) == 1, "%s: expected one armature, got %d" % (source, len(armatures)))
    armature = armatures[0]
    bpy.context.view_layer.objects.active = armature
    disconnect(armature, RIGS[kind]["located"])
    print("character: %s (%s import), %d bones, rotation mode %s" % (
        source, "FBX" if kind == "geno" else "BVH", len(armature.data.bones),
        armature.pose.bones[RIGS[kind]["keyed"][0]].rotation_mode))
    return armature, RIGS[kind]


def walk_on_rig(mocapfill, armature):
    """The first SECONDS of the walk, retargeted by mocapfill onto the armature's own rest skeleton
    (as the add-on reads it), as Blender pose channels: (rest, rotations (F, J, 4) xyzw, locations)."""
    import numpy as np
    from mocapfill_blender import armature_sketch, rig_math
    rest = armature_sketch.read_rig_rest(armature, bpy.context.scene)
    character = mocapfill.Scene.from_skeleton(rest.names, rest.parents, rest.rest_translations, rest.rest_rotations)
    motion = mocapfill.load(WALK)
    clip = motion.clip(0)
    check(abs(clip.rate_hz - FPS) < 1e-6, "%s: expected a %d Hz walk, got %g Hz" % (WALK, FPS, clip.rate_hz))
    frames = int(SECONDS * FPS) + 1
    motion.set_clip(0, mocapfill.Clip(clip.times[:frames], clip.rotations[:frames], clip.translations[:frames],
                                      name="walk", rate_hz=FPS))
    walk = mocapfill.retarget(motion, character).clip(0)
    check(walk.frame_count == frames, "retargeted walk: %d frames, expected %d" % (walk.frame_count, frames))
    rotations, locations = rig_math.local_to_pose(rest, walk.rotations, walk.translations)
    return rest, np.asarray(rotations), np.asarray(locations), walk


def set_rotation(pose_bone, xyzw):
    from mathutils import Quaternion
    q = Quaternion((xyzw[3], xyzw[0], xyzw[1], xyzw[2]))
    if pose_bone.rotation_mode == 'QUATERNION':
        pose_bone.rotation_quaternion = q
        return "rotation_quaternion"
    if pose_bone.rotation_mode == 'AXIS_ANGLE':
        axis, angle = q.to_axis_angle()
        pose_bone.rotation_axis_angle = (angle, *axis)
        return "rotation_axis_angle"
    pose_bone.rotation_euler = q.to_euler(pose_bone.rotation_mode)
    return "rotation_euler"


def key_sketch(armature, rig, rest, rotations, locations):
    """The animator's sketch: a new action keying the hips (rotation, location) and the legs every
    KEY_STEP frames; every other bone at rest. Returns (action, keyed frames)."""
    from mathutils import Matrix
    for pose_bone in armature.pose.bones:  # the importer's pose would otherwise leak into the sketch
        pose_bone.matrix_basis = Matrix.Identity(4)
    if armature.animation_data is None:
        armature.animation_data_create()
    action = bpy.data.actions.new("walk_sketch")
    armature.animation_data.action = action
    frames = list(range(0, rotations.shape[0], KEY_STEP))
    for sample in frames:
        for name in rig["keyed"]:
            j = rest.names.index(name)
            pose_bone = armature.pose.bones[name]
            path = set_rotation(pose_bone, rotations[sample, j])
            pose_bone.keyframe_insert(path, frame=FIRST_FRAME + sample, group=name)
            if name in rig["located"]:
                pose_bone.location = locations[sample, j]
                pose_bone.keyframe_insert("location", frame=FIRST_FRAME + sample, group=name)
    return action, [FIRST_FRAME + f for f in frames]


def joint_positions(rest, rotations, translations):
    """World positions (J, 3), Y up, metres, of one frame of local transforms (forward kinematics)."""
    from mocapfill_blender import rig_math
    import numpy as np
    world_q, world_p = np.zeros((rest.joint_count, 4)), np.zeros((rest.joint_count, 3))
    for j, parent in enumerate(rest.parents):
        if parent < 0:
            world_q[j], world_p[j] = rotations[j], translations[j]
        else:
            world_q[j] = rig_math.quat_multiply(world_q[parent], rotations[j])
            world_p[j] = world_p[parent] + rig_math.quat_rotate(world_q[parent], translations[j])
    return world_p


def check_conventions(armature, rig, rest, walk, key_frames):
    """Blender's evaluation of the sketch puts the legs where mocapfill's forward kinematics of
    the walk does: checks the Y-up conversion, the rest transforms and the pose conventions
    independently of the add-on's own inverse. Returns the worst distance (metres)."""
    worst = 0.0
    legs = set(rig["keyed"]) - set(rig["located"])
    chains = [n for n in rest.names if n in rig["keyed"] or
              (armature.data.bones[n].parent and armature.data.bones[n].parent.name in legs)]
    metres = bpy.context.scene.unit_settings.scale_length
    for frame in key_frames:
        bpy.context.scene.frame_set(frame)
        sample = frame - FIRST_FRAME
        expected = joint_positions(rest, walk.rotations[sample], walk.translations[sample])
        for name in chains:
            x, y, z = armature.matrix_world @ armature.pose.bones[name].head
            got = (x * metres, z * metres, -y * metres)  # Blender Z up -> Y up
            worst = max(worst, math.dist(got, expected[rest.names.index(name)]))
    print("conventions: Blender's legs vs mocapfill's forward kinematics of the walk, %d joints x %d frames: "
          "worst %.2e m" % (len(chains), len(key_frames), worst))
    check(worst < 1e-4, "Blender puts the keyed joints %.4f m from where mocapfill does" % worst)


def snapshot(action):
    return sorted((c.data_path, c.array_index, tuple(tuple(k.co) for k in c.keyframe_points)) for c in action.fcurves)


def pose_at(armature, action, frame, names):
    """{bone: (matrix_basis quaternion, armature-space rotation quaternion, location)} as Blender evaluates them."""
    armature.animation_data.action = action
    bpy.context.scene.frame_set(frame)
    bpy.context.view_layer.update()
    return {n: (armature.pose.bones[n].matrix_basis.to_quaternion(),
                armature.pose.bones[n].matrix.to_quaternion(),
                armature.pose.bones[n].matrix_basis.translation.copy()) for n in names}


def angle_deg(a, b):
    """Angle between two mathutils quaternions, in double precision: mathutils works in float32,
    where acos near 1 cannot resolve angles below about 0.02 deg (coarser than the tolerance)."""
    aw, ax, ay, az = (float(c) for c in a)
    bw, bx, by, bz = (float(c) for c in b)
    w = aw * bw + ax * bx + ay * by + az * bz  # conj(a) * b
    x = aw * bx - ax * bw - ay * bz + az * by
    y = aw * by + ax * bz - ay * bw - az * bx
    z = aw * bz - ax * by + ay * bx - az * bw
    return math.degrees(2.0 * math.atan2(math.sqrt(x * x + y * y + z * z), abs(w)))


def animated_bones(action):
    bones = set()
    for curve in action.fcurves:
        if curve.data_path.startswith('pose.bones["') and ".rotation" in curve.data_path and len(curve.keyframe_points):
            bones.add(curve.data_path.split('"')[1])
    return bones


FILL_OPTIONS = {}


def run_fill(**options):
    return bpy.ops.mocapfill.fill_action(**FILL_OPTIONS, **options)


def test_fill(armature, rig, sketch, key_frames):
    before = snapshot(sketch)
    start = time.perf_counter()
    result = run_fill(method="hierarchical")
    fill_seconds = time.perf_counter() - start
    check(result == {'FINISHED'}, "fill_action returned %s, expected {'FINISHED'}" % result)
    filled = armature.animation_data.action
    check(filled is not None and filled != sketch, "no new action assigned (action: %s)" % filled)
    check(sketch.name in bpy.data.actions and sketch.use_fake_user, "the original action is gone or has no fake user")
    check(snapshot(sketch) == before, "the original action changed")
    print("fill: %.2f s; new action %r, original %r kept (fake user)" % (fill_seconds, filled.name, sketch.name))

    keyed_bones = animated_bones(filled)
    frame_count = int(round(filled.frame_range[1] - filled.frame_range[0])) + 1
    for name in rig["keyed"] + rig["synthesised"]:
        check(name in keyed_bones, "bone %r has no rotation keys in %r" % (name, filled.name))
    for curve in filled.fcurves:
        bone = curve.data_path.split('"')[1] if curve.data_path.startswith("pose.bones") else None
        if bone in rig["keyed"] + rig["synthesised"] and ".rotation" in curve.data_path:
            check(len(curve.keyframe_points) == frame_count,
                  "%s[%d]: %d keys, expected one per frame (%d)" % (curve.data_path, curve.array_index,
                                                                   len(curve.keyframe_points), frame_count))
    located = sorted({c.data_path.split('"')[1] for c in filled.fcurves if c.data_path.endswith("].location")})
    print("new action: %d bones keyed at each of %d frames; location keys on %s" % (len(keyed_bones), frame_count,
                                                                                  ", ".join(located)))

    # The animator's keys hold: local (matrix_basis) and armature-space rotations, hips location.
    worst_local = worst_world = worst_location = 0.0
    worst_local_at = (rig["keyed"][0], key_frames[0])
    for frame in key_frames:
        want = pose_at(armature, sketch, frame, rig["keyed"])
        got = pose_at(armature, filled, frame, rig["keyed"])
        for name in rig["keyed"]:
            local, world = angle_deg(want[name][0], got[name][0]), angle_deg(want[name][1], got[name][1])
            if local > worst_local:
                worst_local, worst_local_at = local, (name, frame)
            worst_world = max(worst_world, world)
        for name in rig["located"]:
            worst_location = max(worst_location, (want[name][2] - got[name][2]).length)
    print("keys: %d frames x %d bones; worst local rotation error %.2e deg (%s at frame %d), worst "
          "armature-space %.2e deg, worst location error %.2e (Blender units)"
          % (len(key_frames), len(rig["keyed"]), worst_local, worst_local_at[0], worst_local_at[1], worst_world,
             worst_location))
    check(worst_local < KEY_TOLERANCE_DEG, "a key moved by %.4f deg (local)" % worst_local)
    check(worst_world < KEY_TOLERANCE_DEG, "a key moved by %.4f deg (armature space)" % worst_world)
    check(worst_location < LOCATION_TOLERANCE_M / armature.matrix_world.to_scale()[0],
          "a location key moved by %.2e" % worst_location)

    # Synthesised bones move.
    start_frame, end_frame = int(filled.frame_range[0]), int(filled.frame_range[1])
    first = pose_at(armature, filled, start_frame, rig["synthesised"])
    turns = {name: 0.0 for name in rig["synthesised"]}
    for frame in range(start_frame, end_frame + 1, 2):
        pose = pose_at(armature, filled, frame, rig["synthesised"])
        for name in turns:
            turns[name] = max(turns[name], angle_deg(first[name][0], pose[name][0]))
    print("synthesised bones turn by: " + ", ".join("%s %.1f deg" % item for item in turns.items()))
    for name, turn in turns.items():
        check(turn > MOVES_DEG, "synthesised bone %r hardly moves (%.2f deg): did mocapfill's coverage blend "
                                "it to the database's mean pose (see the coverage warning above)?" % (name, turn))
    return filled


def test_bad_database(armature, filled):
    """A database that does not exist: CANCELLED with an error report, not a traceback. (bpy.ops
    turns an operator's ERROR report into a RuntimeError carrying the report's text.)"""
    actions_before = set(bpy.data.actions.keys())
    missing = "/nonexistent/mocapfill/no_such.mfdb"
    try:
        result = run_fill(database=missing, method="hierarchical")
        message = ""
    except RuntimeError as e:
        result, message = {'CANCELLED'}, str(e)
    print("bad database: %s, %r" % (result, message.strip()))
    check(result == {'CANCELLED'}, "a missing database gave %s, expected {'CANCELLED'}" % result)
    check("Traceback" not in message and missing in message, "expected an error report naming %s" % missing)
    check(armature.animation_data.action == filled and set(bpy.data.actions.keys()) == actions_before,
          "a failed fill changed the actions")


def main():
    total = time.perf_counter()
    args = arguments()
    if args.coverage != "blend":
        FILL_OPTIONS["coverage"] = args.coverage
    armature, rig = import_character(args.geno)
    from mocapfill_blender import module_loader
    mocapfill = module_loader.import_mocapfill()
    bpy.context.scene.render.fps, bpy.context.scene.render.fps_base = FPS, 1.0
    rest, rotations, locations, walk = walk_on_rig(mocapfill, armature)
    sketch, key_frames = key_sketch(armature, rig, rest, rotations, locations)
    check_conventions(armature, rig, rest, walk, key_frames)
    print("sketch: %d bones keyed at %d frames (%d..%d): %s; location on %s"
          % (len(rig["keyed"]), len(key_frames), key_frames[0], key_frames[-1], ", ".join(rig["keyed"]),
             ", ".join(rig["located"])))
    filled = test_fill(armature, rig, sketch, key_frames)
    test_bad_database(armature, filled)
    print("blender_addon_test: PASSED in %.1f s" % (time.perf_counter() - total))


if __name__ == "__main__":
    try:
        main()
    except Exception:  # noqa: BLE001 - Blender must exit non-zero on any failure
        traceback.print_exc()
        print("blender_addon_test: FAILED")
        sys.stdout.flush()
        sys.exit(1)
    sys.stdout.flush()
    sys.exit(0)
