"""Quaternion and frame conversions between a Blender armature and a mocapfill scene.

No bpy here (numpy only), so the conventions can be tested with any Python:

* Quaternions are numpy arrays (..., 4) in mocapfill's order x, y, z, w. (Blender's
  rotation_quaternion is w, x, y, z: the bpy-side modules reorder.)
* mocapfill scenes are Y up, metres; Blender is Z up. Armature space is taken to the sketch's
  world by ``sketch_world = Y_UP_FROM_Z_UP @ object.matrix_world`` (glTF's convention,
  Blender (x, y, z) -> (x, z, -y), a -90 degree turn about X). The object's world transform is
  part of it because importers put the file's axis and unit conversion there (Blender's FBX
  importer gives a Y-up centimetre file's armature a +90 degree X turn and a 0.01 scale), so
  without it such a character would lie on its back and be 100 times too big.
* A bone's local rest transform is ``parent.matrix_local^-1 @ bone.matrix_local`` (a root bone:
  ``sketch_world @ bone.matrix_local``), its rotation normalised and its translation in metres.
* Blender's pose (matrix_basis) applies in the bone's rest frame, after the rest:
  ``local = rest_local @ Translation(location) @ Rotation(pose)``, so
  ``local_rotation = rest_rotation * pose_rotation`` and
  ``local_translation = rest_translation + rest_rotation * (location * metres_per_unit)``.
"""
import numpy as np

# Blender's Z-up world to mocapfill's Y-up world: (x, y, z) -> (x, z, -y).
Y_UP_FROM_Z_UP = np.array([[1.0, 0.0, 0.0, 0.0],
                           [0.0, 0.0, 1.0, 0.0],
                           [0.0, -1.0, 0.0, 0.0],
                           [0.0, 0.0, 0.0, 1.0]])

# How far from uniform an object's scale may be (relative) before the rig is refused: mocapfill
# joints carry no scale, so a squashed armature has no faithful sketch.
UNIFORM_SCALE_TOLERANCE = 1e-4


class RigError(ValueError):
    """The armature cannot be expressed as a mocapfill skeleton (message says why)."""


def quat_multiply(a, b):
    """Hamilton product a * b of (..., 4) x, y, z, w quaternions (b applied first)."""
    ax, ay, az, aw = np.moveaxis(np.asarray(a, dtype=float), -1, 0)
    bx, by, bz, bw = np.moveaxis(np.asarray(b, dtype=float), -1, 0)
    return np.stack([aw * bx + ax * bw + ay * bz - az * by,
                     aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw,
                     aw * bw - ax * bx - ay * by - az * bz], axis=-1)


def quat_conjugate(q):
    q = np.asarray(q, dtype=float)
    return q * np.array([-1.0, -1.0, -1.0, 1.0])


def quat_normalize(q):
    q = np.asarray(q, dtype=float)
    norm = np.linalg.norm(q, axis=-1, keepdims=True)
    if np.any(norm < 1e-12):
        raise RigError("a rotation quaternion is zero (all four channels 0); expected a unit quaternion")
    return q / norm


def quat_rotate(q, v):
    """Rotates (..., 3) vectors v by (..., 4) unit quaternions q."""
    q = np.asarray(q, dtype=float)
    v = np.asarray(v, dtype=float)
    u, w = q[..., :3], q[..., 3:4]
    t = 2.0 * np.cross(u, v)
    return v + w * t + np.cross(u, t)


def quat_from_matrix(m):
    """The unit quaternion (x, y, z, w) of a 3x3 rotation matrix (Shepperd's method)."""
    m = np.asarray(m, dtype=float)
    trace = m[0, 0] + m[1, 1] + m[2, 2]
    if trace > 0.0:
        s = 2.0 * np.sqrt(trace + 1.0)
        q = [(m[2, 1] - m[1, 2]) / s, (m[0, 2] - m[2, 0]) / s, (m[1, 0] - m[0, 1]) / s, 0.25 * s]
    elif m[0, 0] > m[1, 1] and m[0, 0] > m[2, 2]:
        s = 2.0 * np.sqrt(1.0 + m[0, 0] - m[1, 1] - m[2, 2])
        q = [0.25 * s, (m[0, 1] + m[1, 0]) / s, (m[0, 2] + m[2, 0]) / s, (m[2, 1] - m[1, 2]) / s]
    elif m[1, 1] > m[2, 2]:
        s = 2.0 * np.sqrt(1.0 + m[1, 1] - m[0, 0] - m[2, 2])
        q = [(m[0, 1] + m[1, 0]) / s, 0.25 * s, (m[1, 2] + m[2, 1]) / s, (m[0, 2] - m[2, 0]) / s]
    else:
        s = 2.0 * np.sqrt(1.0 + m[2, 2] - m[0, 0] - m[1, 1])
        q = [(m[0, 2] + m[2, 0]) / s, (m[1, 2] + m[2, 1]) / s, 0.25 * s, (m[1, 0] - m[0, 1]) / s]
    q = np.array(q)
    return q / np.linalg.norm(q)


def quat_angle_deg(a, b):
    """Angle in degrees between the rotations a and b ((..., 4); q and -q are the same rotation)."""
    dots = np.abs(np.sum(quat_normalize(a) * quat_normalize(b), axis=-1))
    return np.degrees(2.0 * np.arccos(np.clip(dots, -1.0, 1.0)))


def make_continuous(q):
    """Flips the sign of (frames, ..., 4) quaternions so consecutive frames lie in the same
    hemisphere: F-curves interpolate channel by channel, and a sign flip between two frames
    would swing the bone through a full turn in between."""
    q = np.array(q, dtype=float)
    for f in range(1, q.shape[0]):
        flip = np.sum(q[f] * q[f - 1], axis=-1) < 0.0
        q[f][flip] *= -1.0
    return q


def uniform_scale(matrix, what):
    """The uniform scale of a 4x4 matrix's 3x3 part; RigError if it is not uniform or mirrors."""
    m = np.asarray(matrix, dtype=float)[:3, :3]
    scales = np.linalg.norm(m, axis=0)
    if scales.min() <= 0.0 or (scales.max() - scales.min()) > UNIFORM_SCALE_TOLERANCE * scales.max():
        raise RigError("%s: scale %s is not uniform; mocapfill skeletons have no scale, so apply the "
                       "scale (Object > Apply > Scale) first" % (what, np.round(scales, 6).tolist()))
    if np.linalg.det(m) < 0.0:
        raise RigError("%s: the transform mirrors (negative scale); apply or remove the negative scale first" % what)
    return float(scales.mean())


class RigRest:
    """A rig's skeleton as mocapfill takes it: joints parent-first, local rest transforms in the
    Y-up sketch world, and the factor from armature units (location channels) to metres."""

    def __init__(self, names, parents, rest_translations, rest_rotations, metres_per_unit):
        self.names = list(names)
        self.parents = list(parents)
        self.rest_translations = np.asarray(rest_translations, dtype=float)  # (J, 3) metres
        self.rest_rotations = np.asarray(rest_rotations, dtype=float)  # (J, 4) x y z w
        self.metres_per_unit = float(metres_per_unit)

    @property
    def joint_count(self):
        return len(self.names)


def order_parent_first(names, parent_names):
    """Joint order with every parent before its children (mocapfill requires parents[j] < j),
    keeping the given order among siblings. Returns (ordered names, parent indices)."""
    children = {name: [] for name in names}
    roots = []
    for name, parent in zip(names, parent_names):
        if parent is None:
            roots.append(name)
        elif parent not in children:
            raise RigError("bone %r: its parent %r is not among the armature's bones" % (name, parent))
        else:
            children[parent].append(name)
    ordered = []
    stack = list(reversed(roots))
    while stack:  # depth first, iterative: rigs may be deeper than Python's recursion limit
        name = stack.pop()
        ordered.append(name)
        stack.extend(reversed(children[name]))
    index = {name: i for i, name in enumerate(ordered)}
    parent_of = dict(zip(names, parent_names))
    return ordered, [index[parent_of[n]] if parent_of[n] is not None else -1 for n in ordered]


def rig_rest_from_bones(names, parent_names, bone_matrices, object_matrix, scene_metres_per_unit=1.0):
    """The rest skeleton of an armature.

    names, parent_names: bone names and their parents' names (None for a root), any order.
    bone_matrices: {name: 4x4 Bone.matrix_local} (armature space, rest).
    object_matrix: the armature object's matrix_world (4x4), which carries importers' axis
    and unit conversions. scene_metres_per_unit: the scene's unit scale (metres per Blender unit).
    """
    if not names:
        raise RigError("the armature has no bones")
    ordered, parents = order_parent_first(names, parent_names)
    object_matrix = np.asarray(object_matrix, dtype=float)
    object_scale = uniform_scale(object_matrix, "armature object")
    metres_per_unit = object_scale * float(scene_metres_per_unit)
    # Metres, Y up; the object's scale taken out again after the root's translation is placed.
    sketch_world = Y_UP_FROM_Z_UP @ object_matrix
    translations = np.zeros((len(ordered), 3))
    rotations = np.zeros((len(ordered), 4))
    for j, name in enumerate(ordered):
        bone = np.asarray(bone_matrices[name], dtype=float)
        if parents[j] < 0:
            local = sketch_world @ bone
            translations[j] = local[:3, 3] * float(scene_metres_per_unit)
            rotation = local[:3, :3] / object_scale
        else:
            parent = np.asarray(bone_matrices[ordered[parents[j]]], dtype=float)
            local = np.linalg.inv(parent) @ bone
            translations[j] = local[:3, 3] * metres_per_unit
            rotation = local[:3, :3]
        rotations[j] = quat_from_matrix(rotation)
    return RigRest(ordered, parents, translations, rotations, metres_per_unit)


def pose_to_local(rest, pose_rotations, pose_locations):
    """Blender pose channels -> mocapfill local transforms.

    pose_rotations: (F, J, 4) x y z w (the bone's rotation channels as a quaternion);
    pose_locations: (F, J, 3) the location channels, armature units, in the bone's rest frame.
    Returns (local rotations (F, J, 4), local translations (F, J, 3) metres)."""
    rotations = quat_multiply(rest.rest_rotations[None], quat_normalize(pose_rotations))
    offsets = quat_rotate(np.broadcast_to(rest.rest_rotations[None], pose_rotations.shape),
                          np.asarray(pose_locations, dtype=float) * rest.metres_per_unit)
    return rotations, rest.rest_translations[None] + offsets


def local_to_pose(rest, local_rotations, local_translations):
    """The inverse of pose_to_local: mocapfill local transforms -> Blender pose channels
    (rotations (F, J, 4) x y z w made continuous in time, locations (F, J, 3) armature units)."""
    inverse_rest = quat_conjugate(rest.rest_rotations)[None]
    rotations = quat_multiply(inverse_rest, quat_normalize(local_rotations))
    shifts = np.asarray(local_translations, dtype=float) - rest.rest_translations[None]
    locations = quat_rotate(np.broadcast_to(inverse_rest, rotations.shape), shifts) / rest.metres_per_unit
    return make_continuous(rotations), locations
