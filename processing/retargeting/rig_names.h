// Joint names as the naming families spell them (Mixamo, Unreal, Unity, Biovision, ...): a
// name is cut into a namespace prefix ("mixamorig:"), a side (Left/Right, L/R, _l/.L, l_),
// a stem ("upleg", "forearm", "spine01") and the words that make a joint a helper (end
// bones, twist halves, IK targets, fingers, face). Names only propose: rig_mapping.cc lets
// the hierarchy and the pose decide.
#pragma once

#include <string>
#include <string_view>

#include "processing/core/skeleton.h"

namespace mocapfill::rig_names {

enum class Side { kNone, kLeft, kRight };

// What the words of a name propose, before the structure is looked at.
enum class NameKind {
  kUnknown,
  kHips,
  kSpine,  // spine, chest, ab, torso, lower back, ribs
  kNeck,
  kHead,
  kShoulder,  // shoulder, clavicle, collar (which one "shoulder" really is, structure decides)
  kUpperArm,
  kLowerArm,
  kHand,
  kUpperLeg,
  kLowerLeg,
  kFoot,
  kToes,
};

struct JointName {
  std::string stem;          // lowercase letters and digits, without prefix, side and separators
  Side side = Side::kNone;
  NameKind kind = NameKind::kUnknown;
  // Non-empty when the name alone says the joint is never a canonical bone: "end bone",
  // "twist helper", "IK helper", "finger", "face", "root above the hips", "hip offset helper".
  std::string helper;
  bool lower_back = false;   // CMU's LowerBack: a helper when the spine has other joints
};

JointName ParseJointName(std::string_view name);

// "left", "right" or "" (for messages).
const char* SideWord(Side side);

// The naming family the joint names belong to: "bandai-namco", "cmu", "mixamo", "geno",
// "unreal", "rigify", "smpl", "biovision", or "unknown".
std::string DetectFamily(const Skeleton& skeleton);


}  // namespace mocapfill::rig_names
