// Left/right mirroring of a clip on its own rig: the motion a performer would have made with
// left and right swapped, reflected across the character's sagittal plane. Local joint frames
// of captured rigs are rarely mirror images of each other (the Bandai-Namco rig's left bones
// point along +X, its right bones along -X), so local rotations cannot be mirrored directly:
// world rotations and positions are reflected, partners swapped, and local rotations rebuilt.
//
// For joint j with partner p (itself on the centre line), with M the reflection:
//   W'_j = M W_p M C_j,   C_j = (M Wrest_p M)^-1 Wrest_j
// where W are world rotations and Wrest a symmetric rest: the rig's canonical T-pose
// (retarget.h: every mapped bone along its canonical direction, the given rest's twists kept)
// for mapped bones, the given rest for other joints. Mirroring twice returns the clip (C_j
// and C_p cancel for any rest). Positions follow from the rotations and the rig's own bone
// offsets, so a mirrored joint misses its reflected partner by what the rest leaves
// asymmetric: on the Bandai-Namco rig, standing in its mean pose, the feet by 0.00 mm and the
// hands by 2.5 mm (the chest's twist between the shoulders); with the mean pose itself as
// the rest, 33 mm and 46 mm.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"
#include "processing/retargeting/rest_pose.h"
#include "processing/retargeting/rig_mapping.h"

namespace mocapfill {

struct MirrorPlan {
  std::vector<int> partner;  // per joint: its left/right partner, or itself
  // Unit normal of the mirror plane (the rig's lateral axis, right to left in the rest); the
  // plane passes through the world origin, so a root's translation is reflected about it.
  Eigen::Vector3d lateral = Eigen::Vector3d::UnitX();
  std::vector<Eigen::Quaterniond> correction;  // C_j per joint

  Eigen::Matrix3d Reflection() const { return Eigen::Matrix3d::Identity() - 2.0 * lateral * lateral.transpose(); }
};

// Each joint's partner: canonical bones by the mapping (leftHand <-> rightHand), other joints
// by their names (Finger1_L / Finger1_R, LeftHandIndex1 / RightHandIndex1, hand.L / hand.R,
// l_thumb / r_thumb, ...); a joint without a partner is its own.
std::vector<int> MirrorPartners(const Skeleton& skeleton, const RigMapping& mapping);

// The plan for `skeleton` standing in `rest` (which must stand: its lateral axis runs from the
// right upper leg to the left one, and the arms' when mapped, seen from above).
// Errors (kInvalidData): the rest does not fit the skeleton; no upper legs; left and right
// hips coincide.
Result<MirrorPlan> PlanMirror(const Skeleton& skeleton, const RigMapping& mapping, const RigRest& rest);

// The mirrored clip (same frames, name and rate). Keyed frames move with their partner joint;
// exact key values are dropped (the keyed frames' samples stand for them).
MotionClip MirrorClip(const Skeleton& skeleton, const MirrorPlan& plan, const MotionClip& clip);

}  // namespace mocapfill
