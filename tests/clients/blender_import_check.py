# Imports .glb files with Blender's own glTF importer and checks that each becomes exactly one
# armature with one bone per joint whose world head positions match mocapfill's forward
# kinematics (mocapfill_fk_dump's JSON) at every frame.
#
# Usage: blender -b --factory-startup --python tests/clients/blender_import_check.py -- \
#            FILE.glb EXPECTED.json [FILE.glb EXPECTED.json ...] [--tolerance-mm 0.01]
# Several files share one Blender start-up. Prints the worst error per file and overall;
# exits 1 when any file fails (Blender's own exit code ignores a script's exceptions).
import json
import os
import sys

import bpy
import numpy

# Blender 3.4's glTF importer uses numpy.bool, which numpy 1.24 removed.
if "bool" not in numpy.__dict__:
    numpy.bool = bool


def clear_scene():
    for collection in (bpy.data.objects, bpy.data.meshes, bpy.data.armatures, bpy.data.actions, bpy.data.materials):
        for item in list(collection):
            collection.remove(item)


def gltf_axes(v):
    # The importer turns glTF's Y-up into Blender's Z-up: (x, y, z) -> (x, -z, y).
    return (v[0], v[2], -v[1])


def check(glb, expected_path, tolerance_m):
    with open(expected_path) as f:
        expected = json.load(f)
    clear_scene()
    scene = bpy.context.scene
    # Keys land on whole frames when the scene runs at the clip's rate.
    rate = expected["rate_hz"]
    scene.render.fps = max(1, round(rate))
    scene.render.fps_base = scene.render.fps / rate
    bpy.ops.import_scene.gltf(filepath=glb, bone_heuristic="TEMPERANCE")
    armatures = [o for o in scene.objects if o.type == "ARMATURE"]
    if len(armatures) != 1:
        return None, "%d armatures (expected 1)" % len(armatures)
    arm = armatures[0]
    joints = expected["joints"]
    bones = [b.name for b in arm.data.bones]
    if sorted(bones) != sorted(joints):
        return None, "bones %s differ from joints %s" % (sorted(bones), sorted(joints))
    action = arm.animation_data.action if arm.animation_data else None
    if action is None:
        return None, "the armature has no action"
    start = round(action.frame_range[0])
    frames = expected["positions"]
    worst, where = 0.0, ""
    for f, positions in enumerate(frames):
        scene.frame_set(start + f)
        evaluated = arm.evaluated_get(bpy.context.evaluated_depsgraph_get())
        world = evaluated.matrix_world
        for name, want in zip(joints, positions):
            head = gltf_axes(world @ evaluated.pose.bones[name].head)
            err = sum((head[a] - want[a]) ** 2 for a in range(3)) ** 0.5
            if err > worst:
                worst, where = err, "%s at frame %d" % (name, f)
    meshes = [o for o in scene.objects if o.type == "MESH"]
    for mesh in meshes:  # the stick figure must deform with the armature
        if not any(m.type == "ARMATURE" and m.object == arm for m in mesh.modifiers):
            return None, "mesh %s is not bound to the armature" % mesh.name
    meshes = len(meshes)
    summary = "%d bones, %d frames, %d mesh objects; worst head error %.6f mm (%s)" % (
        len(bones), len(frames), meshes, worst * 1000.0, where or "-")
    if worst > tolerance_m:
        return worst, "FAILED: " + summary
    return worst, summary


def main():
    args = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    tolerance_m = 0.01e-3
    if "--tolerance-mm" in args:
        i = args.index("--tolerance-mm")
        tolerance_m = float(args[i + 1]) * 1e-3
        del args[i:i + 2]
    if not args or len(args) % 2:
        print("usage: blender -b --factory-startup --python blender_import_check.py -- FILE.glb EXPECTED.json ...")
        sys.exit(2)
    failed = 0
    overall = 0.0
    for glb, expected in zip(args[0::2], args[1::2]):
        try:
            worst, message = check(glb, expected, tolerance_m)
        except Exception as e:  # report the file and go on with the others
            worst, message = None, "FAILED: %s: %s" % (type(e).__name__, e)
        print("blender_import_check: %s: %s" % (glb, message))
        if worst is None or message.startswith("FAILED"):
            failed += 1
        else:
            overall = max(overall, worst)
    print("blender_import_check: %d file(s), %d failed; worst head error %.6f mm (tolerance %.4f mm)" % (
        len(args) // 2, failed, overall * 1000.0, tolerance_m * 1000.0))
    sys.stdout.flush()
    # os._exit: Blender's own exit would report success whatever the script found.
    os._exit(1 if failed else 0)


main()
