#include "processing/motion/mirror.h"

#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "processing/core/kinematics.h"
#include "processing/retargeting/humanoid.h"
#include "processing/retargeting/retarget.h"

namespace mocapfill {

namespace {

using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

// Side spellings as the naming families write them, left first. Where a spelling sits
// (front, back, anywhere) matters: "L" anywhere would match every capital L.
enum class SidePlace { kPrefix, kSuffix, kAnywhere };
struct SideSpelling {
  std::string_view left, right;
  SidePlace place;
};
constexpr std::array<SideSpelling, 19> kSideSpellings{{
    {"Left", "Right", SidePlace::kAnywhere},
    {"left", "right", SidePlace::kAnywhere},
    {"LEFT", "RIGHT", SidePlace::kAnywhere},
    {"_L_", "_R_", SidePlace::kAnywhere},
    {"_l_", "_r_", SidePlace::kAnywhere},
    {".L.", ".R.", SidePlace::kAnywhere},  // Rigify: DEF-upper_arm.L.001
    {".l.", ".r.", SidePlace::kAnywhere},
    {"_L", "_R", SidePlace::kSuffix},
    {"_l", "_r", SidePlace::kSuffix},
    {".L", ".R", SidePlace::kSuffix},
    {".l", ".r", SidePlace::kSuffix},
    {"-L", "-R", SidePlace::kSuffix},
    {" L", " R", SidePlace::kSuffix},
    {"L_", "R_", SidePlace::kPrefix},
    {"l_", "r_", SidePlace::kPrefix},
    {"L.", "R.", SidePlace::kPrefix},
    {"l.", "r.", SidePlace::kPrefix},
    {"L", "R", SidePlace::kPrefix},  // CMU: LHipJoint, RHipJoint
    {"l", "r", SidePlace::kPrefix},  // CMU: lhumerus, rhumerus
}};

// `name` with `from` replaced by `to` at `place`, or nullopt when `from` is not there. A
// prefix counts after a namespace ("mixamorig:LeftHand").
std::optional<std::string> SwapSideSpelling(const std::string& name, std::string_view from, std::string_view to,
                                            SidePlace place) {
  const size_t colon = name.rfind(':');
  const size_t start = colon == std::string::npos ? 0 : colon + 1;
  std::string out = name;
  switch (place) {
    case SidePlace::kPrefix:
      if (name.compare(start, from.size(), from) != 0 || name.size() == start + from.size()) return std::nullopt;
      out.replace(start, from.size(), to);
      return out;
    case SidePlace::kSuffix:
      if (name.size() < start + from.size() + 1 || name.compare(name.size() - from.size(), from.size(), from) != 0)
        return std::nullopt;
      out.replace(name.size() - from.size(), from.size(), to);
      return out;
    case SidePlace::kAnywhere: {
      const size_t at = name.find(from, start);
      if (at == std::string::npos) return std::nullopt;
      out.replace(at, from.size(), to);
      return out;
    }
  }
  return std::nullopt;
}

// The joint whose name is `j`'s with the side swapped, or -1.
int PartnerByName(const Skeleton& skeleton, int j) {
  const std::string& name = skeleton.name(j);
  for (const SideSpelling& s : kSideSpellings) {
    for (int direction = 0; direction < 2; ++direction) {
      const std::string_view from = direction == 0 ? s.left : s.right, to = direction == 0 ? s.right : s.left;
      const std::optional<std::string> swapped = SwapSideSpelling(name, from, to, s.place);
      if (!swapped) continue;
      const std::optional<int> other = skeleton.Find(*swapped);
      if (other && *other != j) return *other;
    }
  }
  return -1;
}

Quaterniond Reflected(const Matrix3d& m, const Quaterniond& q) {
  return Quaterniond(Matrix3d(m * q.toRotationMatrix() * m)).normalized();
}

}  // namespace

std::vector<int> MirrorPartners(const Skeleton& skeleton, const RigMapping& mapping) {
  const int n = skeleton.num_joints();
  std::vector<int> partner(n, -1);
  for (int b = 0; b < kNumHumanoidBones; ++b) {
    const int j = mapping.joints[b];
    const int p = mapping.joint(MirrorBone(BoneAt(b)));
    if (j >= 0 && p >= 0) partner[j] = p;
  }
  for (int j = 0; j < n; ++j) {
    if (partner[j] >= 0 || mapping.BoneOfJoint(j) >= 0) continue;
    const int p = PartnerByName(skeleton, j);
    // Only a pair both of whose names point at each other, and neither a canonical bone
    // (whose partner the mapping decided): a name that happens to swap into another joint's
    // is no pair.
    if (p >= 0 && mapping.BoneOfJoint(p) < 0 && PartnerByName(skeleton, p) == j) partner[j] = p;
  }
  for (int j = 0; j < n; ++j)
    if (partner[j] < 0) partner[j] = j;
  return partner;
}

Result<MirrorPlan> PlanMirror(const Skeleton& skeleton, const RigMapping& mapping, const RigRest& rest) {
  const int n = skeleton.num_joints();
  if (static_cast<int>(rest.local_rotations.size()) != n || static_cast<int>(rest.local_translations.size()) != n)
    return InvalidData("mirror: the rest pose does not fit the skeleton");
  if (!mapping.has(HumanoidBone::kLeftUpperLeg) || !mapping.has(HumanoidBone::kRightUpperLeg))
    return InvalidData("mirror: the rig has no left and right upper legs to tell its sides by");
  const std::vector<Vector3d> positions = rest.WorldPositions(skeleton);
  const auto at = [&](HumanoidBone b) { return positions[mapping.joint(b)]; };
  Vector3d lateral = at(HumanoidBone::kLeftUpperLeg) - at(HumanoidBone::kRightUpperLeg);
  if (mapping.has(HumanoidBone::kLeftUpperArm) && mapping.has(HumanoidBone::kRightUpperArm))
    lateral += at(HumanoidBone::kLeftUpperArm) - at(HumanoidBone::kRightUpperArm);
  // Seen from above (+Y is up once imported): a rest whose pelvis rolls a little must not tilt
  // the plane the character is reflected in.
  lateral.y() = 0.0;
  if (lateral.norm() < 1e-6)
    return InvalidData("mirror: the rest pose shows no left-right extent (left and right hips coincide seen from above)");

  MirrorPlan plan;
  plan.lateral = lateral.normalized();
  plan.partner = MirrorPartners(skeleton, mapping);
  // A captured rest (a mean pose) is never quite symmetric: a degree between the legs moves a
  // mirrored foot by centimetres. The canonical T-pose of the rig (retarget.h) points every
  // mapped bone exactly along its canonical direction, mirror images by construction, keeping
  // only the rest's twists; its frame's +X is the same lateral axis.
  std::vector<Quaterniond> rotations = rest.WorldRotations(skeleton);
  if (Result<HumanoidRig> rig = HumanoidRig::Make(skeleton, mapping, rest); rig.ok()) {
    plan.lateral = rig->frame() * Vector3d::UnitX();
    for (int b = 0; b < kNumHumanoidBones; ++b)
      if (mapping.joints[b] >= 0) rotations[mapping.joints[b]] = rig->frame() * rig->t_pose_rotation(BoneAt(b));
  }
  const Matrix3d m = plan.Reflection();
  plan.correction.resize(n);
  for (int j = 0; j < n; ++j)
    plan.correction[j] = (Reflected(m, rotations[plan.partner[j]]).conjugate() * rotations[j]).normalized();
  return plan;
}

MotionClip MirrorClip(const Skeleton& skeleton, const MirrorPlan& plan, const MotionClip& clip) {
  const int n = skeleton.num_joints();
  const Matrix3d m = plan.Reflection();
  MotionClip out = clip;
  std::vector<bool> positioned(n);
  for (int j = 0; j < n; ++j) {
    const int p = plan.partner[j];
    positioned[j] = skeleton.parent(j) == kNoParent ? clip.translation_animated[j] != 0
                                                     : clip.translation_animated[j] || clip.translation_animated[p];
    out.translation_animated[j] = positioned[j] || clip.translation_animated[j];
    out.keys[j] = clip.keys[p];
    JointKeys& k = out.keys[j];
    k.rotation_times_s.clear();
    k.rotation_values.clear();
    k.translation_times_s.clear();
    k.translation_values.clear();
  }
  WorldPose pose;
  std::vector<Quaterniond> world(n);
  std::vector<Vector3d> placed(n);
  for (int f = 0; f < clip.num_frames; ++f) {
    ComputeWorldPose(skeleton, clip, f, pose);
    for (int j = 0; j < n; ++j) {
      const int p = plan.partner[j], parent = skeleton.parent(j);
      world[j] = (Reflected(m, pose.rotations[p]) * plan.correction[j]).normalized();
      Vector3d& t = out.translation(f, j);
      if (positioned[j]) {
        const Vector3d target = m * pose.positions[p];
        t = parent == kNoParent ? target
                                : Vector3d((world[parent].conjugate() * (target - placed[parent]))
                                               .cwiseQuotient(skeleton.joint(parent).rest_scale));
      }
      placed[j] = parent == kNoParent ? t : Vector3d(placed[parent] + world[parent] * skeleton.joint(parent).rest_scale.cwiseProduct(t));
      out.rotation(f, j) = parent == kNoParent ? world[j] : (world[parent].conjugate() * world[j]).normalized();
    }
  }
  out.MakeContinuous();
  return out;
}

}  // namespace mocapfill
