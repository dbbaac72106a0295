#include "processing/retargeting/rig_names.h"

#include <algorithm>
#include <cctype>
#include <initializer_list>
#include <vector>

namespace mocapfill::rig_names {

namespace {

std::string Lower(std::string_view s) {
  std::string out(s);
  for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

bool StartsWith(std::string_view s, std::string_view prefix) { return s.substr(0, prefix.size()) == prefix; }
bool EndsWith(std::string_view s, std::string_view suffix) {
  return s.size() >= suffix.size() && s.substr(s.size() - suffix.size()) == suffix;
}
bool Contains(std::string_view s, std::string_view part) { return s.find(part) != std::string_view::npos; }
bool IsSeparator(char c) { return c == '_' || c == '.' || c == '-' || c == ' '; }

bool OneOf(std::string_view s, std::initializer_list<std::string_view> words) {
  return std::find(words.begin(), words.end(), s) != words.end();
}

// The stem without trailing digits: "spine01" -> "spine", "neck1" -> "neck".
std::string_view WithoutDigits(std::string_view stem) {
  while (!stem.empty() && std::isdigit(static_cast<unsigned char>(stem.back()))) stem.remove_suffix(1);
  return stem;
}

// Cuts a side off the front or back of `name` (original case: CMU's "LHipJoint" is told from
// "LowerBack" by the capital after the L).
Side CutSide(std::string& name) {
  const std::string lower = Lower(name);
  for (std::string_view word : {"left", "right"}) {
    if (StartsWith(lower, word) && lower.size() > word.size()) {
      name.erase(0, word.size());
      return word == "left" ? Side::kLeft : Side::kRight;
    }
    if (lower.size() > word.size() + 1 && EndsWith(lower, word) && IsSeparator(lower[lower.size() - word.size() - 1])) {
      name.erase(name.size() - word.size() - 1);
      return word == "left" ? Side::kLeft : Side::kRight;
    }
  }
  if (lower.size() > 2 && (lower[0] == 'l' || lower[0] == 'r') && IsSeparator(lower[1])) {  // l_hip, R_Knee
    const Side side = lower[0] == 'l' ? Side::kLeft : Side::kRight;
    name.erase(0, 2);
    return side;
  }
  if (lower.size() > 2 && (EndsWith(lower, "l") || EndsWith(lower, "r")) && IsSeparator(lower[lower.size() - 2])) {
    const Side side = lower.back() == 'l' ? Side::kLeft : Side::kRight;  // thigh_l, Hand_L, foot.L
    name.erase(name.size() - 2);
    return side;
  }
  if (name.size() > 2 && (name[0] == 'L' || name[0] == 'R') && std::isupper(static_cast<unsigned char>(name[1]))) {
    const Side side = name[0] == 'L' ? Side::kLeft : Side::kRight;  // LHipJoint, RThumb
    name.erase(0, 1);
    return side;
  }
  return Side::kNone;
}

NameKind KindOfStem(std::string_view stem, Side side) {
  const std::string_view word = WithoutDigits(stem);
  if (side == Side::kNone && OneOf(word, {"hips", "hip", "pelvis"})) return NameKind::kHips;
  if (side == Side::kNone &&
      (StartsWith(word, "spine") || OneOf(word, {"chest", "upperchest", "ab", "abdomen", "torso", "waist", "lowerback",
                                                 "back", "ribs"})))
    return NameKind::kSpine;
  if (StartsWith(word, "neck")) return NameKind::kNeck;
  if (word == "head") return NameKind::kHead;
  if (side == Side::kNone) return NameKind::kUnknown;
  if (OneOf(word, {"shoulder", "clavicle", "collar"})) return NameKind::kShoulder;
  if (OneOf(word, {"arm", "upperarm", "uparm"})) return NameKind::kUpperArm;
  if (OneOf(word, {"forearm", "lowerarm", "loarm", "elbow"})) return NameKind::kLowerArm;
  if (OneOf(word, {"hand", "wrist"})) return NameKind::kHand;
  if (OneOf(word, {"upleg", "upperleg", "thigh", "hip"})) return NameKind::kUpperLeg;
  if (OneOf(word, {"leg", "lowerleg", "loleg", "calf", "shin", "knee"})) return NameKind::kLowerLeg;
  if (OneOf(word, {"foot", "ankle"})) return NameKind::kFoot;
  if (OneOf(word, {"toe", "toes", "toebase", "ball"})) return NameKind::kToes;
  return NameKind::kUnknown;
}

std::string HelperOf(std::string_view stem, Side side, bool numbered_half) {
  const std::string_view word = WithoutDigits(stem);
  if (EndsWith(word, "end") || EndsWith(word, "nub") || Contains(word, "site")) return "end bone";
  if (Contains(stem, "twist") || Contains(stem, "roll")) return "twist helper";
  if (StartsWith(stem, "ik")) return "IK helper";
  for (std::string_view f : {"thumb", "index", "middle", "ring", "pinky", "little", "finger", "palm"})
    if (Contains(stem, f)) return "finger";
  for (std::string_view f : {"eye", "jaw", "nose", "lip", "brow", "lid", "ear", "tongue", "teeth", "face", "breast"})
    if (StartsWith(stem, f)) return "face or body detail";
  if (OneOf(word, {"root", "jointroot", "armature", "reference", "master"})) return "root above the hips";
  if (word == "hipjoint") return "hip offset helper";
  if (side != Side::kNone && word == "pelvis") return "pelvis helper";
  if (numbered_half && side != Side::kNone) return "twist helper";  // Rigify's DEF-forearm.L.001
  return "";
}

}  // namespace

JointName ParseJointName(std::string_view full_name) {
  std::string name(full_name);
  // Namespaces: "mixamorig:Hips", "Armature|Hips", "ns:rig:Hips".
  const size_t cut = name.find_last_of(":|");
  if (cut != std::string::npos && cut + 1 < name.size()) name.erase(0, cut + 1);
  // Rigify's deform layer.
  if (StartsWith(Lower(name), "def-")) name.erase(0, 4);
  // Rigify numbers segments ".001": a twist half on a limb, a spine segment on the trunk.
  bool numbered_half = false;
  if (name.size() > 4 && name[name.size() - 4] == '.' &&
      std::all_of(name.end() - 3, name.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
    const std::string base = name.substr(0, name.size() - 4);
    std::string probe = base;
    if (CutSide(probe) != Side::kNone) {
      numbered_half = true;
      name = base;
    }
  }
  JointName out;
  out.side = CutSide(name);
  for (char c : name)
    if (std::isalnum(static_cast<unsigned char>(c))) out.stem += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  out.helper = HelperOf(out.stem, out.side, numbered_half);
  out.kind = out.helper.empty() ? KindOfStem(out.stem, out.side) : NameKind::kUnknown;
  out.lower_back = WithoutDigits(out.stem) == "lowerback";
  return out;
}

const char* SideWord(Side side) {
  switch (side) {
    case Side::kLeft: return "left";
    case Side::kRight: return "right";
    case Side::kNone: break;
  }
  return "";
}

std::string DetectFamily(const Skeleton& skeleton) {
  auto has = [&](std::string_view n) { return skeleton.Find(n).has_value(); };
  bool mixamo_prefix = false, rigify = false;
  for (const Joint& j : skeleton.joints()) {
    mixamo_prefix |= StartsWith(j.name, "mixamorig");
    rigify |= StartsWith(j.name, "DEF-");
  }
  if (mixamo_prefix) return "mixamo";
  if (rigify) return "rigify";
  if (has("pelvis") && (has("thigh_l") || has("upperarm_l"))) return "unreal";
  if (has("L_Hip") || has("L_Collar")) return "smpl";
  if (has("UpperArm_L") || has("Shoulder_L")) return "bandai-namco";
  if (has("LHipJoint")) return "cmu";
  if (has("LeftCollar") || has("LeftElbow")) return "biovision";
  if (has("Spine3") && has("Neck1") && has("LeftUpLeg")) return "geno";
  if (has("LeftUpLeg") && has("Spine2")) return "mixamo";
  return "unknown";
}

}  // namespace mocapfill::rig_names
