// The canonical humanoid every rig is mapped to: the bone set of VRM 1.0 humanoid and Unity's
// HumanBodyBones (fingers, eyes and jaw left out: joints outside this set keep the rig's own
// values). Bones are named with VRM's spelling ("hips", "leftUpperArm", ...).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string_view>

namespace mocapfill {

enum class HumanoidBone : int {
  kHips,
  kSpine,
  kChest,
  kUpperChest,
  kNeck,
  kHead,
  kLeftShoulder,
  kLeftUpperArm,
  kLeftLowerArm,
  kLeftHand,
  kRightShoulder,
  kRightUpperArm,
  kRightLowerArm,
  kRightHand,
  kLeftUpperLeg,
  kLeftLowerLeg,
  kLeftFoot,
  kLeftToes,
  kRightUpperLeg,
  kRightLowerLeg,
  kRightFoot,
  kRightToes,
};
constexpr int kNumHumanoidBones = 22;

inline HumanoidBone BoneAt(int i) { return static_cast<HumanoidBone>(i); }
inline int BoneIndex(HumanoidBone b) { return static_cast<int>(b); }

// "hips", "leftUpperArm", ... (VRM 1.0 spelling).
const char* HumanoidBoneName(HumanoidBone bone);
// The bone of a VRM name, case-insensitive; nullopt for anything else.
std::optional<HumanoidBone> ParseHumanoidBone(std::string_view name);
// Required in VRM 1.0: hips, spine, head, upper/lower arms, hands, upper/lower legs, feet.
bool IsRequiredBone(HumanoidBone bone);
// The canonical parent (hips: nullopt). chest's parent is spine, upperChest's chest, neck's
// upperChest, shoulders' upperChest, upper arms' shoulders, upper legs' hips, ...
std::optional<HumanoidBone> CanonicalParent(HumanoidBone bone);
// The mirrored bone (leftHand <-> rightHand); torso bones map to themselves.
HumanoidBone MirrorBone(HumanoidBone bone);

// The canonical T-pose in the canonical frame (Y up, the character facing +Z, its left at
// +X): the unit direction in which each bone points (towards its canonical child: legs
// down, arms out to the sides, spine, neck and head up, feet and toes forward).
Eigen::Vector3d CanonicalDirection(HumanoidBone bone);

}  // namespace mocapfill
