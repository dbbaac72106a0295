// Automatic humanoid mapping. Names propose, structure decides:
//   1. the upper legs and the hands are found by name (with their side); those the names miss
//      (no side word, or no name at all) by the rest pose (rig_limbs_by_pose.h);
//   2. each leg is walked down (upper leg, lower leg, foot, toes) and each arm up from the
//      hand (lower arm, upper arm, then a side joint under the torso is the shoulder): so
//      SMPL's L_Shoulder and the Biovision LeftShoulder become upper arms, and SMPL's L_Foot
//      the toes, whatever their words say;
//   3. the hips are where the legs meet; the torso is the chain from the hips up to the joint
//      the arms branch from; the head is named "head" (or ends the neck chain);
//   4. sides are checked against the pose (toes ahead of ankles give forward), and a user map
//      overrides any pair.
#include "processing/retargeting/rig_mapping.h"

#include <algorithm>
#include <functional>
#include <set>
#include <sstream>

#include "processing/retargeting/rig_limbs_by_pose.h"
#include "processing/retargeting/rig_names.h"
#include "processing/retargeting/rig_structure.h"

namespace mocapfill {

namespace {

using rig_names::JointName;
using rig_names::NameKind;
using rig_names::Side;
using B = HumanoidBone;

std::string Quoted(const std::string& s) { return "'" + s + "'"; }

std::string JoinNames(const Skeleton& skeleton, const std::vector<int>& joints) {
  if (joints.empty()) return "none";
  std::string out;
  for (int j : joints) out += (out.empty() ? "" : ", ") + Quoted(skeleton.name(j));
  return out;
}

NameKind KindOfBone(HumanoidBone bone) {
  switch (bone) {
    case B::kHips: return NameKind::kHips;
    case B::kSpine:
    case B::kChest:
    case B::kUpperChest: return NameKind::kSpine;
    case B::kNeck: return NameKind::kNeck;
    case B::kHead: return NameKind::kHead;
    case B::kLeftShoulder:
    case B::kRightShoulder: return NameKind::kShoulder;
    case B::kLeftUpperArm:
    case B::kRightUpperArm: return NameKind::kUpperArm;
    case B::kLeftLowerArm:
    case B::kRightLowerArm: return NameKind::kLowerArm;
    case B::kLeftHand:
    case B::kRightHand: return NameKind::kHand;
    case B::kLeftUpperLeg:
    case B::kRightUpperLeg: return NameKind::kUpperLeg;
    case B::kLeftLowerLeg:
    case B::kRightLowerLeg: return NameKind::kLowerLeg;
    case B::kLeftFoot:
    case B::kRightFoot: return NameKind::kFoot;
    case B::kLeftToes:
    case B::kRightToes: return NameKind::kToes;
  }
  return NameKind::kUnknown;
}

// What the automatic pass found, before overrides and the required-bone check.
struct AutoResult {
  RigMapping mapping;
  std::vector<std::string> hips_problem;  // non-empty: the hips could not be decided (message parts)
  std::string pose_problem;  // why the pose did not show the limbs the names missed
};

void MapLeg(const RigStructure& rig, int upper, bool left, RigMapping& m) {
  const HumanoidBone bones[4] = {left ? B::kLeftUpperLeg : B::kRightUpperLeg, left ? B::kLeftLowerLeg : B::kRightLowerLeg,
                                 left ? B::kLeftFoot : B::kRightFoot, left ? B::kLeftToes : B::kRightToes};
  int j = upper;
  for (HumanoidBone bone : bones) {
    if (j < 0) break;
    m.joints[BoneIndex(bone)] = j;
    j = rig.NextDown(j);
  }
}

// Returns the joint the arm hangs from (the torso joint), or -1.
int MapArm(const RigStructure& rig, int hand, int other_hand, bool left, RigMapping& m) {
  const int lower = rig.PrevUp(hand);
  const int upper = lower >= 0 ? rig.PrevUp(lower) : -1;
  if (upper < 0) return -1;
  m.joints[BoneIndex(left ? B::kLeftHand : B::kRightHand)] = hand;
  m.joints[BoneIndex(left ? B::kLeftLowerArm : B::kRightLowerArm)] = lower;
  m.joints[BoneIndex(left ? B::kLeftUpperArm : B::kRightUpperArm)] = upper;
  const int above = rig.PrevUp(upper);
  if (above < 0) return -1;
  // A clavicle is a side joint between the torso and the upper arm; a torso joint (no side,
  // the neck's parent) is where the arm starts directly. A joint whose name says nothing is a
  // clavicle when the other arm does not hang from it.
  const rig_names::JointName& said = rig.name(above);
  const bool unnamed_side_joint =
      said.kind == NameKind::kUnknown && said.side == Side::kNone && other_hand >= 0 && !rig.IsAncestor(above, other_hand);
  if (said.side != Side::kNone || said.kind == NameKind::kShoulder || unnamed_side_joint) {
    m.joints[BoneIndex(left ? B::kLeftShoulder : B::kRightShoulder)] = above;
    return rig.PrevUp(above);
  }
  return above;
}

void MapTorso(const RigStructure& rig, int hips, int top, RigMapping& m) {
  std::vector<int> chain = rig.TorsoChain(hips, top);
  const int n = static_cast<int>(chain.size());
  if (n == 0) return;
  m.joints[BoneIndex(B::kSpine)] = chain[0];
  if (n == 2) m.joints[BoneIndex(B::kChest)] = chain[1];
  if (n >= 3) {
    // The top joint (where arms and neck branch) is the upper chest, the one below it the
    // chest; joints between spine and chest stay unmapped and fold into the spine when
    // retargeting (Geno: spine Spine, chest Spine2, upperChest Spine3; Spine1 folded).
    m.joints[BoneIndex(B::kUpperChest)] = chain[n - 1];
    m.joints[BoneIndex(B::kChest)] = chain[n - 2];
    if (n > 3) {
      std::vector<int> folded(chain.begin() + 1, chain.end() - 2);
      m.notes.push_back("torso of " + std::to_string(n) + " joints: spine " + Quoted(rig.skeleton().name(chain[0])) +
                        ", chest " + Quoted(rig.skeleton().name(chain[n - 2])) + ", upperChest " +
                        Quoted(rig.skeleton().name(chain[n - 1])) + "; " + JoinNames(rig.skeleton(), folded) +
                        " left between spine and chest");
    }
  }
}

void MapNeckAndHead(const RigStructure& rig, int top, RigMapping& m) {
  // The joints above the top torso joint, head last.
  std::vector<int> chain = rig.NeckChain(top, {m.joint(B::kLeftHand), m.joint(B::kRightHand)});
  if (chain.empty()) return;
  m.joints[BoneIndex(B::kHead)] = chain.back();
  if (chain.size() >= 2) m.joints[BoneIndex(B::kNeck)] = chain.front();
  if (chain.size() > 2) {
    std::vector<int> extra(chain.begin() + 1, chain.end() - 1);
    m.notes.push_back("neck of " + std::to_string(chain.size() - 1) + " joints: neck " +
                      Quoted(rig.skeleton().name(chain.front())) + "; " + JoinNames(rig.skeleton(), extra) +
                      " left between neck and head");
  }
}

// The joint a user override sends to `bone`, or -1.
int OverriddenJoint(const Skeleton& skeleton, const std::map<std::string, std::string>& overrides, B bone) {
  for (const auto& [joint, target] : overrides) {
    const auto parsed = ParseHumanoidBone(target);
    const auto j = skeleton.Find(joint);
    if (parsed && *parsed == bone && j) return *j;
  }
  return -1;
}

// The chains start from the upper legs and the hands: named ones, or those a user override
// names (so that overriding a hand the names miss maps its whole arm).
// Fills the anchors the names missed from the limbs the pose shows (rig_limbs_by_pose.h).
void AnchorsFromPose(const RigStructure& rig, const std::vector<Eigen::Vector3d>& pose, int legs[2], int hands[2],
                     AutoResult& out) {
  if (legs[0] >= 0 && legs[1] >= 0 && hands[0] >= 0 && hands[1] >= 0) return;
  if (pose.empty()) return;
  std::optional<LimbsByPose> limbs = FindLimbsByPose(rig, pose, out.pose_problem);
  if (!limbs) return;
  const auto fill = [](int named[2], const int seen[2]) {
    for (int side = 0; side < 2; ++side)
      if (named[side] < 0 && seen[side] >= 0 && seen[side] != named[1 - side]) named[side] = seen[side];
    if (named[0] >= 0 && named[0] == named[1]) named[1] = -1;
  };
  const int before[4] = {legs[0], legs[1], hands[0], hands[1]};
  fill(legs, limbs->upper_leg);
  fill(hands, limbs->hand);
  std::string found;
  const int after[4] = {legs[0], legs[1], hands[0], hands[1]};
  const char* what[4] = {"leftUpperLeg", "rightUpperLeg", "leftHand", "rightHand"};
  for (int i = 0; i < 4; ++i)
    if (before[i] < 0 && after[i] >= 0)
      found += (found.empty() ? "" : ", ") + std::string(what[i]) + " " + Quoted(rig.skeleton().name(after[i]));
  if (found.empty()) return;
  out.mapping.notes.push_back("found by the rest pose, not by name: " + found);
  if (!limbs->sides_seen)
    out.mapping.warnings.push_back("the rest pose shows no forward direction (no toes ahead of the ankles): left "
                                   "and right of the limbs found by pose are a guess; a --map can fix them");
}

AutoResult MapAutomatically(const RigStructure& rig, const std::vector<Eigen::Vector3d>& pose,
                            const std::map<std::string, std::string>& overrides) {
  AutoResult out;
  RigMapping& m = out.mapping;
  m.family = rig_names::DetectFamily(rig.skeleton());
  const auto anchor = [&](B bone, NameKind kind, Side side) {
    const int given = OverriddenJoint(rig.skeleton(), overrides, bone);
    return given >= 0 ? given : rig.BestByName(kind, side);
  };
  int legs[2] = {anchor(B::kLeftUpperLeg, NameKind::kUpperLeg, Side::kLeft),
                 anchor(B::kRightUpperLeg, NameKind::kUpperLeg, Side::kRight)};
  int hands[2] = {anchor(B::kLeftHand, NameKind::kHand, Side::kLeft),
                  anchor(B::kRightHand, NameKind::kHand, Side::kRight)};
  AnchorsFromPose(rig, pose, legs, hands, out);
  const int leg_l = legs[0], leg_r = legs[1], hand_l = hands[0], hand_r = hands[1];
  if (leg_l >= 0) MapLeg(rig, leg_l, true, m);
  if (leg_r >= 0) MapLeg(rig, leg_r, false, m);
  const int top_l = hand_l >= 0 ? MapArm(rig, hand_l, hand_r, true, m) : -1;
  const int top_r = hand_r >= 0 ? MapArm(rig, hand_r, hand_l, false, m) : -1;

  // Hips: where the legs meet; else the one joint named like hips.
  const std::vector<int> hips_named = rig.AllByName(NameKind::kHips);
  int hips = -1;
  if (leg_l >= 0 && leg_r >= 0) {
    hips = rig.skeleton().HierarchyDistance(leg_l, leg_r) >= 0 ? rig.CommonAncestor(leg_l, leg_r) : -1;
    if (hips < 0) {
      if (hips_named.size() >= 2)
        out.hips_problem.push_back("two candidates for the hips: " + JoinNames(rig.skeleton(), hips_named) +
                                   " (the legs " + Quoted(rig.skeleton().name(leg_l)) + " and " +
                                   Quoted(rig.skeleton().name(leg_r)) + " hang from different joints)");
      else
        out.hips_problem.push_back("the legs " + Quoted(rig.skeleton().name(leg_l)) + " and " +
                                   Quoted(rig.skeleton().name(leg_r)) + " do not meet at a hips joint");
    }
  } else if (hips_named.size() == 1) {
    hips = hips_named[0];
  } else if (hips_named.size() >= 2) {
    out.hips_problem.push_back("two candidates for the hips: " + JoinNames(rig.skeleton(), hips_named));
  }
  if (hips >= 0) m.joints[BoneIndex(B::kHips)] = hips;

  // The torso top: the joint both arms hang from (the upper chest).
  int top = top_l >= 0 ? top_l : top_r;
  if (top_l >= 0 && top_r >= 0 && top_l != top_r) {
    top = rig.CommonAncestor(top_l, top_r);
    m.notes.push_back("the arms hang from different torso joints (" + Quoted(rig.skeleton().name(top_l)) + ", " +
                      Quoted(rig.skeleton().name(top_r)) + "); the torso ends at " +
                      (top >= 0 ? Quoted(rig.skeleton().name(top)) : std::string("none")));
  }
  if (hips >= 0 && top >= 0 && rig.IsAncestor(hips, top)) {
    MapTorso(rig, hips, top, m);
    MapNeckAndHead(rig, top, m);
  } else if (hips >= 0) {
    // No arms: the torso is the chain up from the hips, its named head (if any) on top.
    const int head = rig.BestByName(NameKind::kHead, Side::kNone);
    if (head >= 0 && rig.IsAncestor(hips, head)) {
      std::vector<int> path = rig.TorsoChain(hips, head);
      path.pop_back();
      if (!path.empty()) m.joints[BoneIndex(B::kSpine)] = path.front();
      m.joints[BoneIndex(B::kHead)] = head;
    }
  }
  return out;
}

// Checks sides against the pose; swaps a pair whose names contradict the geometry.
void CheckSides(const RigStructure& rig, const std::vector<Eigen::Vector3d>& pose, RigMapping& m) {
  const Skeleton& skeleton = rig.skeleton();
  if (pose.size() != static_cast<size_t>(skeleton.num_joints())) {
    m.notes.emplace_back("no pose given: left and right decided by names");
    return;
  }
  const std::optional<Eigen::Matrix3d> frame = rig.BodyFrame(m, pose);
  if (!frame) {
    m.notes.emplace_back(
        "the pose does not show which way the rig faces (toes not ahead of the ankles, or the head not above the "
        "hips): left and right decided by names");
    return;
  }
  const Eigen::Vector3d left = frame->col(0);
  struct Pair {
    const char* what;
    std::vector<HumanoidBone> left_bones;
  };
  const Pair pairs[] = {
      {"leg", {B::kLeftUpperLeg, B::kLeftLowerLeg, B::kLeftFoot, B::kLeftToes}},
      {"arm", {B::kLeftShoulder, B::kLeftUpperArm, B::kLeftLowerArm, B::kLeftHand}},
  };
  bool decided = false;
  for (const Pair& pair : pairs) {
    // Compare the limb's second joint (upper leg's knee side, upper arm): far enough from the
    // midline to tell the sides apart even when the roots sit close together.
    const int a = m.joint(pair.left_bones[1]);
    const int b = m.joint(MirrorBone(pair.left_bones[1]));
    if (a < 0 || b < 0) continue;
    const double separation = (pose[a] - pose[b]).dot(left);
    const double scale = std::max(1e-6, (pose[a] - pose[b]).norm());
    if (std::abs(separation) < 0.2 * scale) {
      m.notes.push_back(std::string("the ") + pair.what + "s are not apart sideways in the pose: their sides decided by names");
      continue;
    }
    decided = true;
    if (separation > 0) continue;
    m.warnings.push_back(std::string("the names put ") + Quoted(skeleton.name(a)) + " on the left, but in the pose it is on the character's right (forward from toes ahead of ankles, up from the hips to the head): geometry wins, the " +
                         pair.what + "s are swapped");
    for (HumanoidBone bone : pair.left_bones) std::swap(m.joints[BoneIndex(bone)], m.joints[BoneIndex(MirrorBone(bone))]);
  }
  if (decided) m.notes.push_back("left and right checked against the pose (toes ahead of the ankles give forward)");
}

std::string ValidBoneNames() {
  std::string out;
  for (int i = 0; i < kNumHumanoidBones; ++i) out += (i ? ", " : "") + std::string(HumanoidBoneName(BoneAt(i)));
  return out;
}

Status ApplyOverrides(const Skeleton& skeleton, const std::map<std::string, std::string>& overrides, RigMapping& m) {
  std::map<int, std::string> sent_to;  // bone -> joint name, to catch two joints sent to one bone
  for (const auto& [joint_name, bone_name] : overrides) {
    const std::optional<int> joint = skeleton.Find(joint_name);
    if (!joint) {
      return FindJointNamed(skeleton, joint_name, "rig map", ErrorCode::kInvalidData).status();
    }
    for (int& j : m.joints)
      if (j == *joint) j = -1;
    if (bone_name.empty()) {
      m.notes.push_back("map: " + Quoted(joint_name) + " left unmapped");
      continue;
    }
    const std::optional<HumanoidBone> bone = ParseHumanoidBone(bone_name);
    if (!bone)
      return InvalidData("rig map: " + Quoted(joint_name) + " -> " + Quoted(bone_name) +
                         ": no such humanoid bone (valid: " + ValidBoneNames() + ")");
    if (auto it = sent_to.find(BoneIndex(*bone)); it != sent_to.end())
      return InvalidData("rig map: two joints sent to " + std::string(HumanoidBoneName(*bone)) + ": " +
                         Quoted(it->second) + " and " + Quoted(joint_name));
    sent_to[BoneIndex(*bone)] = joint_name;
    m.joints[BoneIndex(*bone)] = *joint;
    m.notes.push_back("map: " + Quoted(joint_name) + " -> " + HumanoidBoneName(*bone));
  }
  return OkStatus();
}

Status CheckRequired(const RigStructure& rig, const AutoResult& automatic, const RigMapping& m,
                     const std::map<std::string, std::string>& overrides) {
  std::vector<HumanoidBone> missing;
  for (int i = 0; i < kNumHumanoidBones; ++i)
    if (IsRequiredBone(BoneAt(i)) && !m.has(BoneAt(i))) missing.push_back(BoneAt(i));
  if (missing.empty()) return OkStatus();
  std::string names;
  for (HumanoidBone b : missing) names += (names.empty() ? "" : ", ") + std::string(HumanoidBoneName(b));
  const bool no_limbs = rig.AllByName(NameKind::kUpperLeg).empty() && rig.AllByName(NameKind::kHand).empty() &&
                        overrides.empty();
  if (no_limbs && m.joint(B::kLeftUpperLeg) < 0 && m.joint(B::kLeftHand) < 0)
    return InvalidData("not a humanoid rig: no joint is named like a leg (UpLeg, UpperLeg, Thigh, Hip) or a hand "
                       "(Hand, Wrist)" +
                       (automatic.pose_problem.empty() ? std::string() : ", and " + automatic.pose_problem) +
                       "; required bones missing: " + names);
  std::string detail;
  const bool hips_missing = std::find(missing.begin(), missing.end(), B::kHips) != missing.end();
  if (hips_missing && !automatic.hips_problem.empty()) {
    for (const std::string& p : automatic.hips_problem) detail += "; " + p;
  }
  if (!automatic.pose_problem.empty()) detail += "; by the rest pose: " + automatic.pose_problem;
  for (HumanoidBone b : missing) {
    if (b == B::kHips && !automatic.hips_problem.empty()) continue;
    detail += "; no " + std::string(HumanoidBoneName(b)) + ": candidates considered: " +
              JoinNames(rig.skeleton(), rig.AllByName(KindOfBone(b)));
  }
  return InvalidData("required humanoid bones missing: " + names + detail + " (a --map can name them)");
}

// Notes where a joint's words propose another bone than the structure gave it ("L_Shoulder"
// is the upper arm when its parent is the collar).
void NoteNameStructureDisagreements(const RigStructure& rig, RigMapping& m) {
  for (int i = 0; i < kNumHumanoidBones; ++i) {
    const int j = m.joints[i];
    if (j < 0) continue;
    const NameKind said = rig.name(j).kind;
    if (said == NameKind::kUnknown || said == KindOfBone(BoneAt(i))) continue;
    if (said == NameKind::kSpine && KindOfBone(BoneAt(i)) == NameKind::kHips) continue;
    m.notes.push_back(Quoted(rig.skeleton().name(j)) + " is " + HumanoidBoneName(BoneAt(i)) +
                      " by the hierarchy (its name suggests another bone)");
  }
}

}  // namespace

int RigMapping::BoneOfJoint(int joint) const {
  for (int i = 0; i < kNumHumanoidBones; ++i)
    if (joints[i] == joint) return i;
  return -1;
}

Result<RigMapping> MapHumanoid(const Skeleton& skeleton, const std::vector<Eigen::Vector3d>& pose_world_positions,
                               const RigMapOptions& options) {
  const RigStructure rig(skeleton);
  AutoResult automatic = MapAutomatically(rig, pose_world_positions, options.overrides);
  RigMapping& m = automatic.mapping;
  CheckSides(rig, pose_world_positions, m);
  NoteNameStructureDisagreements(rig, m);
  RETURN_IF_ERROR(ApplyOverrides(skeleton, options.overrides, m));
  RETURN_IF_ERROR(CheckRequired(rig, automatic, m, options.overrides));
  return std::move(m);
}

std::string UnmappedJointReason(const Skeleton& skeleton, const RigMapping& mapping, int joint) {
  if (mapping.BoneOfJoint(joint) >= 0) return "";
  const JointName name = rig_names::ParseJointName(skeleton.name(joint));
  if (!name.helper.empty()) return name.helper;
  const RigStructure rig(skeleton);
  const int hips = mapping.joint(B::kHips);
  const int head = mapping.joint(B::kHead);
  if (hips >= 0 && rig.IsAncestor(joint, hips)) return "root above the hips";
  for (B end : {B::kLeftHand, B::kRightHand})
    if (mapping.has(end) && rig.IsAncestor(mapping.joint(end), joint)) return "below the hand (fingers, hand end)";
  for (B end : {B::kLeftToes, B::kRightToes, B::kLeftFoot, B::kRightFoot})
    if (mapping.has(end) && rig.IsAncestor(mapping.joint(end), joint)) return "below the foot (toe or heel end)";
  if (hips >= 0 && head >= 0 && rig.IsAncestor(hips, joint) && rig.IsAncestor(joint, head))
    return name.lower_back ? "lower-back helper (spine offset)" : "extra spine or neck joint (folded into its neighbours)";
  return "not a canonical bone";
}

}  // namespace mocapfill
