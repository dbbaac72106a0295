// Automatic mapping of a rig's joints to the canonical humanoid (humanoid.h): joint names
// propose (the naming families in common use: Bandai-Namco, CMU, Mixamo, Geno/ZeroEGGS/LaFAN1,
// Unreal Mannequin, Blender Rigify, SMPL, Biovision; prefixes such as "mixamorig:" and side
// spellings Left/Right/L/R/_l/.L), the hierarchy and the rest positions decide (chains from
// the hips: legs below it, arms off the chest, the elbow one joint above the hand; left and
// right from geometry where the pose shows them). A user map overrides any pair.
#pragma once

#include <Eigen/Core>
#include <array>
#include <map>
#include <string>
#include <vector>

#include "processing/core/skeleton.h"
#include "processing/core/status.h"
#include "processing/retargeting/humanoid.h"

namespace mocapfill {

struct RigMapping {
  // Per canonical bone (BoneIndex): the skeleton joint, or -1 when the rig has no such bone.
  std::array<int, kNumHumanoidBones> joints;
  std::string family;               // naming family recognised: "bandai-namco", "cmu", "mixamo", ...
  std::vector<std::string> notes;   // how ambiguous choices were decided (shown by `rig show`)
  std::vector<std::string> warnings;  // e.g. a side name that contradicts the geometry

  RigMapping() { joints.fill(-1); }
  int joint(HumanoidBone bone) const { return joints[BoneIndex(bone)]; }
  bool has(HumanoidBone bone) const { return joint(bone) >= 0; }
  // The canonical bone of a skeleton joint, or -1.
  int BoneOfJoint(int joint) const;
};

struct RigMapOptions {
  // Overrides: skeleton joint name -> canonical bone name (VRM spelling, any case), or "" to
  // leave the joint unmapped. Applied after the automatic mapping.
  std::map<std::string, std::string> overrides;
};

// Maps `skeleton` to the canonical humanoid. `pose_world_positions` (one per joint, metres)
// is a pose that shows the rig's layout (its rest pose; see rest_pose.h) and is used only to
// confirm structure and sides; pass an empty vector to decide by names and hierarchy alone.
// Errors (kInvalidData): a required bone not found ("no leftUpperLeg: candidates considered:
// ..." naming the joints looked at, or that the rig is not humanoid and which required bones
// are missing); two joints competing for the hips; an override naming an unknown joint (with
// the closest joint names) or an unknown bone; two joints sent to one bone.
Result<RigMapping> MapHumanoid(const Skeleton& skeleton, const std::vector<Eigen::Vector3d>& pose_world_positions,
                               const RigMapOptions& options = {});

// Why a joint has no canonical bone, for reports: "end bone", "twist helper", "finger",
// "root above the hips", "extra spine or neck joint (folded into its neighbours)", ...;
// "" for a mapped joint.
std::string UnmappedJointReason(const Skeleton& skeleton, const RigMapping& mapping, int joint);

}  // namespace mocapfill
