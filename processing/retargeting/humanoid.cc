#include "processing/retargeting/humanoid.h"

#include <array>
#include <cctype>

namespace mocapfill {

namespace {

using B = HumanoidBone;

struct BoneInfo {
  const char* name;
  bool required;
  int parent;  // BoneIndex of the canonical parent, -1 for the hips
  int mirror;  // BoneIndex of the mirrored bone
};

// One row per HumanoidBone, in enum order. Parents follow VRM 1.0 with every optional bone
// present (a rig without chest or upperChest skips them: CanonicalParent does not).
constexpr std::array<BoneInfo, kNumHumanoidBones> kBones = {{
    {"hips", true, -1, 0},
    {"spine", true, 0, 1},
    {"chest", false, 1, 2},
    {"upperChest", false, 2, 3},
    {"neck", false, 3, 4},
    {"head", true, 4, 5},
    {"leftShoulder", false, 3, 10},
    {"leftUpperArm", true, 6, 11},
    {"leftLowerArm", true, 7, 12},
    {"leftHand", true, 8, 13},
    {"rightShoulder", false, 3, 6},
    {"rightUpperArm", true, 10, 7},
    {"rightLowerArm", true, 11, 8},
    {"rightHand", true, 12, 9},
    {"leftUpperLeg", true, 0, 18},
    {"leftLowerLeg", true, 14, 19},
    {"leftFoot", true, 15, 20},
    {"leftToes", false, 16, 21},
    {"rightUpperLeg", true, 0, 14},
    {"rightLowerLeg", true, 18, 15},
    {"rightFoot", true, 19, 16},
    {"rightToes", false, 20, 17},
}};

bool EqualsIgnoreCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

}  // namespace

const char* HumanoidBoneName(HumanoidBone bone) { return kBones[BoneIndex(bone)].name; }

std::optional<HumanoidBone> ParseHumanoidBone(std::string_view name) {
  for (int i = 0; i < kNumHumanoidBones; ++i)
    if (EqualsIgnoreCase(name, kBones[i].name)) return BoneAt(i);
  return std::nullopt;
}

bool IsRequiredBone(HumanoidBone bone) { return kBones[BoneIndex(bone)].required; }

std::optional<HumanoidBone> CanonicalParent(HumanoidBone bone) {
  const int parent = kBones[BoneIndex(bone)].parent;
  if (parent < 0) return std::nullopt;
  return BoneAt(parent);
}

HumanoidBone MirrorBone(HumanoidBone bone) { return BoneAt(kBones[BoneIndex(bone)].mirror); }

Eigen::Vector3d CanonicalDirection(HumanoidBone bone) {
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  const Eigen::Vector3d forward = Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d left = Eigen::Vector3d::UnitX();  // the character's left, facing +Z
  switch (bone) {
    case B::kHips:
    case B::kSpine:
    case B::kChest:
    case B::kUpperChest:
    case B::kNeck:
    case B::kHead: return up;
    case B::kLeftShoulder:
    case B::kLeftUpperArm:
    case B::kLeftLowerArm:
    case B::kLeftHand: return left;
    case B::kRightShoulder:
    case B::kRightUpperArm:
    case B::kRightLowerArm:
    case B::kRightHand: return -left;
    case B::kLeftUpperLeg:
    case B::kLeftLowerLeg:
    case B::kRightUpperLeg:
    case B::kRightLowerLeg: return -up;
    case B::kLeftFoot:
    case B::kLeftToes:
    case B::kRightFoot:
    case B::kRightToes: return forward;
  }
  return up;
}

}  // namespace mocapfill
