"""Writes a filled clip into a new action, leaving the original action untouched.

The new action starts as a copy of the original (so curves the fill does not produce survive:
scale, custom properties, bones mocapfill kept), then every filled bone's rotation curves are
replaced by a key at every frame. Rotations are written in the bone's own rotation mode
(quaternion, Euler of the bone's order, or axis-angle), so the bone's settings and the original
action stay valid; Euler angles are made continuous from frame to frame. Locations are written
for root bones (their translation is the walk) and for bones the original action moved.
"""
import numpy as np
from mathutils import Quaternion

from .armature_sketch import ROTATION_PATHS, EULER_PATH, rotation_path


def quaternions_to_channels(mode, rotations_xyzw):
    """(F, 4) x y z w -> list of per-frame channel tuples in the bone's rotation mode."""
    quats = [Quaternion((w, x, y, z)) for x, y, z, w in rotations_xyzw]
    if mode == 'QUATERNION':
        return [tuple(q) for q in quats]
    if mode == 'AXIS_ANGLE':
        channels = []
        for q in quats:
            axis, angle = q.to_axis_angle()
            channels.append((angle, axis[0], axis[1], axis[2]))
        return channels
    channels, previous = [], None
    for q in quats:
        euler = q.to_euler(mode, previous) if previous is not None else q.to_euler(mode)
        channels.append(tuple(euler))
        previous = euler
    return channels


def remove_curves(action, paths):
    for curve in [c for c in action.fcurves if c.data_path in paths]:
        action.fcurves.remove(curve)


def add_curves(action, path, group, frames, channels):
    """One F-curve per channel with a key at every frame (auto-clamped Bezier, Blender's default)."""
    values = np.asarray(channels, dtype=float)
    for index in range(values.shape[1]):
        curve = action.fcurves.new(path, index=index, action_group=group)
        curve.keyframe_points.add(len(frames))
        co = np.empty(2 * len(frames))
        co[0::2] = frames
        co[1::2] = values[:, index]
        curve.keyframe_points.foreach_set("co", co)
        curve.update()  # sorts the keys and computes their handles


def write_filled_action(armature_object, original, frames, pose_rotations, pose_locations, joint_names,
                        bones_to_key, bones_with_location, name):
    """Creates and assigns the new action.

    frames: frame numbers of the samples; pose_rotations (F, J, 4) x y z w and pose_locations
    (F, J, 3) are pose channels in joint_names order. bones_to_key: names whose rotation is
    written; bones_with_location: those whose location is written too.
    """
    action = original.copy()
    action.name = name
    action.use_fake_user = False
    original.use_fake_user = True  # the animator's own action stays in the file, assigned or not
    pose_bones = armature_object.pose.bones
    index = {n: j for j, n in enumerate(joint_names)}
    replaced = set()
    for bone_name in bones_to_key:
        pose_bone = pose_bones[bone_name]
        replaced.update(pose_bone.path_from_id(p) for p in set(ROTATION_PATHS.values()) | {EULER_PATH})
        if bone_name in bones_with_location:
            replaced.add(pose_bone.path_from_id("location"))
    remove_curves(action, replaced)
    for bone_name in bones_to_key:
        pose_bone = pose_bones[bone_name]
        j = index[bone_name]
        channels = quaternions_to_channels(pose_bone.rotation_mode, pose_rotations[:, j])
        add_curves(action, pose_bone.path_from_id(rotation_path(pose_bone)), bone_name, frames, channels)
        if bone_name in bones_with_location:
            add_curves(action, pose_bone.path_from_id("location"), bone_name, frames, pose_locations[:, j])
    if armature_object.animation_data is None:
        armature_object.animation_data_create()
    armature_object.animation_data.action = action
    return action
