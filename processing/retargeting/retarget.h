// Rest-pose-aware retargeting through the canonical humanoid. Each rig is prepared once
// (HumanoidRig): from its rest pose it gets the rotation from the canonical frame (Y up,
// facing +Z, left +X) to its own axes, and per canonical bone the world rotation that joint
// would have if the rig stood in the canonical T-pose (each bone straightened relative to
// its parent, so a bone keeps the twist it has relative to its parent in the rest). A motion's world rotations taken
// relative to that T-pose are rig independent (CanonicalMotion); on another rig they are
// applied relative to its T-pose. So world bone directions carry over whatever the two rigs'
// rest poses (T-pose, A-pose, a captured frame) and local axis conventions, and the hips'
// translation is scaled by the ratio of hip heights.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"
#include "processing/retargeting/humanoid.h"
#include "processing/retargeting/rest_pose.h"
#include "processing/retargeting/rig_mapping.h"

namespace mocapfill {

class HumanoidRig {
 public:
  // Errors (kInvalidData): the mapping lacks the hips or both upper legs; the rest pose does
  // not fit the skeleton; the rest pose shows no left-right extent (sides cannot be told).
  static Result<HumanoidRig> Make(const Skeleton& skeleton, const RigMapping& mapping, const RigRest& rest);

  // This rig's geometry (frame, T-pose, hip height, mapping, rest) on `skeleton`, another
  // skeleton of the same rig (SameRig): retargeting between the two copies local rotations
  // exactly, whatever end sites or bone lengths either skeleton was read with.
  HumanoidRig OnSkeleton(const Skeleton& skeleton) const {
    HumanoidRig rig = *this;
    rig.skeleton_ = skeleton;
    return rig;
  }

  const Skeleton& skeleton() const { return skeleton_; }
  const RigMapping& mapping() const { return mapping_; }
  const RigRest& rest() const { return rest_; }
  // Rotation taking canonical axes to the rig's world axes (its up and forward at rest).
  const Eigen::Quaterniond& frame() const { return frame_; }
  // Height of the hips above the ankles with the legs straight (metres): the root's scale.
  double hip_height_m() const { return hip_height_m_; }
  // World rotation of the bone's joint when the rig stands in the canonical T-pose,
  // expressed in canonical axes (only for mapped bones).
  const Eigen::Quaterniond& t_pose_rotation(HumanoidBone bone) const { return t_pose_[BoneIndex(bone)]; }
  // The joint a bone points at when joints the canonical set does not name lie between them
  // (CMU's Neck1 between neck and head): reading a motion aims the bone at it. -1 otherwise.
  int aim_joint(HumanoidBone bone) const { return aim_joint_[BoneIndex(bone)]; }

 private:
  Skeleton skeleton_;
  RigMapping mapping_;
  RigRest rest_;
  Eigen::Quaterniond frame_ = Eigen::Quaterniond::Identity();
  double hip_height_m_ = 1.0;
  std::array<Eigen::Quaterniond, kNumHumanoidBones> t_pose_;
  std::array<int, kNumHumanoidBones> aim_joint_;
};

// A motion on the canonical humanoid: per frame and bone, the bone's world rotation relative
// to the canonical T-pose (identity there), in canonical axes; the hips' position in canonical
// axes divided by the rig's hip height; and the keys of each bone's source joint.
struct CanonicalMotion {
  double sample_rate_hz = 30.0;
  int num_frames = 0;
  std::array<bool, kNumHumanoidBones> present{};  // the source rig has the bone
  std::vector<Eigen::Quaterniond> rotations;      // [f * kNumHumanoidBones + b]
  std::vector<Eigen::Vector3d> hips;              // per frame, in hip heights
  std::array<JointKeys, kNumHumanoidBones> keys;  // rotation keys of the bone's joint; hips' translation keys

  const Eigen::Quaterniond& rotation(int f, HumanoidBone b) const {
    return rotations[static_cast<size_t>(f) * kNumHumanoidBones + BoneIndex(b)];
  }
};

CanonicalMotion ToCanonical(const HumanoidRig& rig, const MotionClip& clip);

// The canonical motion on `rig`. Joints outside the canonical set (fingers, twist and end
// bones, helpers such as CMU's LHipJoint) keep the values of `base` (a clip on `rig` with the
// same frame count), or the rig's rest pose when base is null. Where a torso bone of the rig
// has no counterpart in the motion (an upperChest the source lacks, extra spine joints), the
// rotation between the nearest mapped torso bones is shared evenly along the chain. Keys: a
// mapped joint takes its bone's keys; other joints keep base's (none without base).
MotionClip FromCanonical(const HumanoidRig& rig, const CanonicalMotion& motion, const MotionClip* base = nullptr);

// ToCanonical then FromCanonical onto `to` at rest for unmapped joints.
MotionClip RetargetClip(const HumanoidRig& from, const MotionClip& clip, const HumanoidRig& to);

// True when two skeletons are one rig: the same joint names and parents, and rest offsets
// pointing the same way (lengths may differ), except those of `translating` joints (by
// index; a motion's joints whose translation is animated): their offsets hold no structure
// (the Bandai-Namco takes write the hips' first position there, up to 4.5 m from the root).
// Such rigs should share one rest pose, so that retargeting between them copies local
// rotations exactly.
bool SameRig(const Skeleton& a, const Skeleton& b, const std::vector<std::uint8_t>& translating = {});

}  // namespace mocapfill
