"""Reads an armature and its action as a mocapfill sketch.

The sketch's keyed joints are the bones whose rotation F-curves (of the bone's own rotation
mode) have keyframes; their keys are those keyframes' frames. Every bone is sampled at every
integer frame of the action's range (so keys on integer frames are exact): the F-curves are
evaluated directly (not the NLA or constraints: the fill works on the action's own values),
and a channel without an F-curve takes the pose bone's current value.
"""
import math

import numpy as np
from mathutils import Euler, Quaternion

from . import rig_math

ROTATION_PATHS = {"QUATERNION": "rotation_quaternion", "AXIS_ANGLE": "rotation_axis_angle"}
EULER_PATH = "rotation_euler"
# Keys further than this (frames) from an integer frame are reported: they are sampled at the
# nearest integer frame, where the F-curve's value is not the key's.
SUBFRAME_TOLERANCE = 1e-3


def rotation_path(pose_bone):
    """The F-curve property that drives a pose bone's rotation in its rotation mode."""
    return ROTATION_PATHS.get(pose_bone.rotation_mode, EULER_PATH)


def scene_fps(scene):
    return scene.render.fps / scene.render.fps_base


def scene_metres_per_unit(scene):
    """Metres per Blender unit: the unit scale when the scene uses units (Blender's internal
    unit is the metre times scale_length), else 1."""
    units = scene.unit_settings
    return units.scale_length if units.system != 'NONE' else 1.0


def read_rig_rest(armature_object, scene):
    """The armature's rest skeleton (rig_math.RigRest) from its bones' rest matrices."""
    bones = armature_object.data.bones
    names = [b.name for b in bones]
    parents = [b.parent.name if b.parent else None for b in bones]
    matrices = {b.name: np.array(b.matrix_local) for b in bones}
    try:
        return rig_math.rig_rest_from_bones(names, parents, matrices, np.array(armature_object.matrix_world),
                                            scene_metres_per_unit(scene))
    except rig_math.RigError as e:
        raise rig_math.RigError("armature %r: %s" % (armature_object.name, e)) from None


class ActionSamples:
    """An action sampled at every integer frame, per joint of a RigRest."""

    def __init__(self, frames, pose_rotations, pose_locations, rotation_keys, translation_keys, warnings):
        self.frames = frames  # integer frame numbers, one per sample
        self.pose_rotations = pose_rotations  # (F, J, 4) x y z w
        self.pose_locations = pose_locations  # (F, J, 3) armature units, bone rest frame
        self.rotation_keys = rotation_keys  # per joint: sample indices of its rotation keys
        self.translation_keys = translation_keys  # per joint: sample indices of its location keys
        self.warnings = warnings

    def keyed_joints(self):
        return [j for j, keys in enumerate(self.rotation_keys) if keys]


def frame_range(action):
    start, end = action.frame_range
    return int(math.floor(start + SUBFRAME_TOLERANCE)), int(math.ceil(end - SUBFRAME_TOLERANCE))


def curves_by_path(action):
    curves = {}
    for curve in action.fcurves:
        curves.setdefault(curve.data_path, {})[curve.array_index] = curve
    return curves


def sample_channels(channel_curves, default_values, frames):
    """(F, len(default_values)) values: each channel's F-curve evaluated, or its default."""
    values = np.tile(np.asarray(default_values, dtype=float), (len(frames), 1))
    for index, curve in channel_curves.items():
        if index < values.shape[1]:
            values[:, index] = [curve.evaluate(f) for f in frames]
    return values


def channels_to_quaternions(mode, values):
    """(F, n) rotation channel values of a rotation mode -> (F, 4) x y z w."""
    if mode == 'QUATERNION':
        quats = [(w, x, y, z) for w, x, y, z in values]
    elif mode == 'AXIS_ANGLE':
        quats = [Quaternion((x, y, z), angle) if (x, y, z) != (0.0, 0.0, 0.0) else Quaternion()
                 for angle, x, y, z in values]
    else:  # an Euler order
        quats = [Euler(v, mode).to_quaternion() for v in values]
    wxyz = np.array([tuple(q) for q in quats], dtype=float)
    return wxyz[:, [1, 2, 3, 0]]


def key_samples(channel_curves, start, sample_count, what, warnings):
    """Sample indices of the keyframes on these F-curves (rounded to integer frames)."""
    keys = set()
    for curve in channel_curves.values():
        for point in curve.keyframe_points:
            frame = point.co.x
            nearest = int(round(frame))
            if abs(frame - nearest) > SUBFRAME_TOLERANCE:
                warnings.append("%s: key at frame %.3f is between frames; kept at frame %d's value"
                                % (what, frame, nearest))
            if 0 <= nearest - start < sample_count:
                keys.add(nearest - start)
    return sorted(keys)


def read_action_samples(armature_object, action, rest):
    """Samples the action on the rig (joint order of rest)."""
    start, end = frame_range(action)
    frames = list(range(start, end + 1))
    if len(frames) < 2:
        raise rig_math.RigError("action %r spans a single frame (%d); a sketch needs keys at two frames or more"
                                % (action.name, start))
    curves = curves_by_path(action)
    count = rest.joint_count
    rotations = np.zeros((len(frames), count, 4))
    locations = np.zeros((len(frames), count, 3))
    rotation_keys, translation_keys, warnings = [], [], []
    for j, name in enumerate(rest.names):
        pose_bone = armature_object.pose.bones[name]
        mode = pose_bone.rotation_mode
        path = pose_bone.path_from_id(rotation_path(pose_bone))
        defaults = getattr(pose_bone, rotation_path(pose_bone))
        rotation_curves = curves.get(path, {})
        values = sample_channels(rotation_curves, tuple(defaults), frames)
        rotations[:, j] = channels_to_quaternions(mode, values)
        rotation_keys.append(key_samples(rotation_curves, start, len(frames), "bone %r rotation" % name, warnings))
        for other in set(ROTATION_PATHS.values()) | {EULER_PATH}:
            other_path = pose_bone.path_from_id(other)
            if other_path != path and other_path in curves:
                warnings.append("bone %r: %s is keyed but the bone's rotation mode is %s; those keys are ignored"
                                % (name, other, mode))
        location_path = pose_bone.path_from_id("location")
        location_curves = curves.get(location_path, {})
        bone = pose_bone.bone
        if bone.use_connect:
            # Blender ignores the location of a bone connected to its parent: so does the sketch.
            if location_curves:
                warnings.append("bone %r is connected to its parent, so Blender ignores its location keys" % name)
            translation_keys.append([])
            continue
        locations[:, j] = sample_channels(location_curves, tuple(pose_bone.location), frames)
        translation_keys.append(key_samples(location_curves, start, len(frames), "bone %r location" % name, warnings))
        if rotation_keys[-1] and (not bone.use_inherit_rotation or not bone.use_local_location):
            warnings.append("bone %r does not inherit its parent's rotation or has a non-local location; "
                            "mocapfill assumes both, so it may not match" % name)
    return ActionSamples(frames, rotations, locations, rotation_keys, translation_keys, warnings)


def build_sketch(mocapfill, rest, samples, fps, name):
    """The mocapfill.Scene of the sketch: the rig at rest plus one clip of the sampled action."""
    scene = mocapfill.Scene.from_skeleton(rest.names, rest.parents, rest.rest_translations, rest.rest_rotations)
    local_rotations, local_translations = rig_math.pose_to_local(rest, samples.pose_rotations,
                                                                 samples.pose_locations)
    times = (np.asarray(samples.frames, dtype=float) - samples.frames[0]) / fps
    scene.add_clip(mocapfill.Clip(times, np.ascontiguousarray(local_rotations),
                                  np.ascontiguousarray(local_translations),
                                  rotation_keys=samples.rotation_keys, translation_keys=samples.translation_keys,
                                  name=name, rate_hz=fps))
    return scene
