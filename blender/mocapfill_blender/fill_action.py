"""The fill itself, as Blender sees it: active armature + action in, new action out.

Kept apart from the operator class so that the steps read in order and the operator only
deals with Blender's UI (reports, progress, cancelling).
"""
import bpy
import numpy as np

from . import action_writer, armature_sketch, module_loader, rig_math

# A bone whose filled translation strays this far (metres) from its rest translation carries
# motion (the hips of a rig with a separate root bone) and gets location keys.
MOVING_TRANSLATION_M = 1e-5


class FillResult:
    def __init__(self, action, keyed_bones, frame_count, key_error_max_deg, warnings):
        self.action = action
        self.keyed_bones = keyed_bones
        self.frame_count = frame_count
        self.key_error_max_deg = key_error_max_deg
        self.warnings = warnings


def active_armature_and_action(context):
    obj = context.active_object
    if obj is None or obj.type != 'ARMATURE':
        raise rig_math.RigError("the active object is %s; select an armature with an action to fill"
                                % ("missing" if obj is None else "a %s (%r)" % (obj.type.lower(), obj.name)))
    if obj.mode == 'EDIT':
        raise rig_math.RigError("armature %r is in Edit Mode; leave it (Tab) so its rest bones are up to date"
                                % obj.name)
    action = obj.animation_data.action if obj.animation_data else None
    if action is None:
        raise rig_math.RigError("armature %r has no action; key some bones (I in Pose Mode) first" % obj.name)
    return obj, action


def open_database(mocapfill, path):
    """The database at path ('' = the default database that ships with mocapfill)."""
    path = path.strip()
    return mocapfill.Database.open(bpy.path.abspath(path) if path else None)


def bones_needing_location(armature_object, rest, samples, local_translations, bones_to_key, warnings):
    """Keyed bones whose location is written: roots, bones the original action moved, and
    bones the fill moved away from their rest translation. A bone connected to its parent
    cannot move in Blender: its translation is dropped, with a warning when the fill moved it."""
    shift = np.linalg.norm(local_translations - rest.rest_translations[None], axis=2).max(axis=0)
    with_location = set()
    for j, name in enumerate(rest.names):
        if name not in bones_to_key:
            continue
        if armature_object.data.bones[name].use_connect:
            if shift[j] > MOVING_TRANSLATION_M:
                warnings.append("bone %r is connected to its parent, so the %.3f m mocapfill moves it by cannot "
                                "be keyed; disconnect it (Edit Mode, Bone > Relations) to keep that motion"
                                % (name, shift[j]))
        elif rest.parents[j] < 0 or samples.translation_keys[j] or shift[j] > MOVING_TRANSLATION_M:
            with_location.add(name)
    return with_location


def output_frames(clip, first_frame, fps):
    return [first_frame + int(round(t * fps)) for t in clip.times]


def fill_active_armature(context, database_path, method, coverage, progress):
    """Runs the fill on the active armature's action; progress(fraction, text) reports steps."""
    progress(0.0, "loading mocapfill")
    mocapfill = module_loader.import_mocapfill()
    obj, original = active_armature_and_action(context)
    scene = context.scene
    fps = armature_sketch.scene_fps(scene)

    progress(0.1, "reading %r" % original.name)
    rest = armature_sketch.read_rig_rest(obj, scene)
    samples = armature_sketch.read_action_samples(obj, original, rest)
    if not samples.keyed_joints():
        raise rig_math.RigError("action %r keys no bone rotation; the sketch's keys are the keyframes on "
                                "pose bones' rotation F-curves" % original.name)
    sketch = armature_sketch.build_sketch(mocapfill, rest, samples, fps, original.name)

    progress(0.2, "opening the database")
    database = open_database(mocapfill, database_path)

    progress(0.3, "filling %d frames (%s)" % (len(samples.frames), method))
    filled, report = mocapfill.fill(sketch, database, method=method, coverage=coverage)
    if list(filled.joint_names) != rest.names:
        raise rig_math.RigError("mocapfill returned joints %s, expected the armature's %s"
                                % (filled.joint_names, rest.names))

    progress(0.8, "writing the new action")
    clip = filled.clip(0)
    local_rotations, local_translations = clip.rotations, clip.translations
    pose_rotations, pose_locations = rig_math.local_to_pose(rest, local_rotations, local_translations)
    kinds = {entry["joint"]: entry["kind"] for entry in report.get("joints", [])}
    bones_to_key = [name for name in rest.names if kinds.get(name, "kept") != "kept"]
    warnings = list(samples.warnings)
    with_location = bones_needing_location(obj, rest, samples, local_translations, bones_to_key, warnings)
    action = action_writer.write_filled_action(obj, original, output_frames(clip, samples.frames[0], fps),
                                               pose_rotations, pose_locations, rest.names, bones_to_key,
                                               with_location, original.name + "_filled")
    warnings += [str(w) for w in report.get("warnings", [])]
    progress(1.0, "done")
    return FillResult(action, bones_to_key, clip.frame_count, report.get("key_error_max_deg", float("nan")),
                      warnings)
