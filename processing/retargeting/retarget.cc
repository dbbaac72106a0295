#include "processing/retargeting/retarget.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>

#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"

namespace mocapfill {

namespace {

using B = HumanoidBone;

using Eigen::Matrix3d;
using Eigen::Quaterniond;
using Eigen::Vector3d;

constexpr double kMinSegmentM = 1e-4;  // shorter offsets (end bones at their parent) show no direction

// An orthonormal frame whose first axis is `d` and whose second lies in the plane of d and
// `ref`: the pelvis's frame from its left-right axis and the world up.
Matrix3d Frame(Vector3d d, const Vector3d& ref) {
  d.normalize();
  Vector3d r = ref - ref.dot(d) * d;
  if (r.norm() < 1e-6) {
    // ref along the bone: any perpendicular will do, chosen deterministically.
    const Vector3d other = std::abs(d.x()) < 0.9 ? Vector3d::UnitX() : Vector3d::UnitY();
    r = other - other.dot(d) * d;
  }
  r.normalize();
  Matrix3d m;
  m.col(0) = d;
  m.col(1) = r;
  m.col(2) = d.cross(r);
  return m;
}

bool IsTorso(HumanoidBone b) {
  return b == HumanoidBone::kSpine || b == HumanoidBone::kChest || b == HumanoidBone::kUpperChest ||
         b == HumanoidBone::kNeck || b == HumanoidBone::kHead;
}

std::string Lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

// Where a bone points at rest when no mapped bone follows it: its children (preferring a
// middle finger for a hand), or its end site.
std::optional<Vector3d> ChildTarget(const Skeleton& skeleton, int joint, const std::vector<Vector3d>& positions,
                                    const std::vector<Quaterniond>& rotations) {
  Vector3d sum = Vector3d::Zero();
  int count = 0;
  for (int c : skeleton.Children(joint)) {
    if ((positions[c] - positions[joint]).norm() < kMinSegmentM) continue;
    if (Lower(skeleton.name(c)).find("middle") != std::string::npos) return positions[c];
    sum += positions[c];
    ++count;
  }
  if (count > 0) return Vector3d(sum / count);
  if (const auto& end = skeleton.joint(joint).end_site; end && end->norm() >= kMinSegmentM)
    return Vector3d(positions[joint] + rotations[joint] * *end);
  return std::nullopt;
}

// The mapped bones that follow `bone` in the canonical T-pose direction, nearest first.
std::vector<HumanoidBone> DirectionBones(HumanoidBone bone) {
  switch (bone) {
    case B::kSpine: return {B::kChest, B::kUpperChest, B::kNeck, B::kHead};
    case B::kChest: return {B::kUpperChest, B::kNeck, B::kHead};
    case B::kUpperChest: return {B::kNeck, B::kHead};
    case B::kNeck: return {B::kHead};
    case B::kLeftShoulder: return {B::kLeftUpperArm};
    case B::kLeftUpperArm: return {B::kLeftLowerArm};
    case B::kLeftLowerArm: return {B::kLeftHand};
    case B::kRightShoulder: return {B::kRightUpperArm};
    case B::kRightUpperArm: return {B::kRightLowerArm};
    case B::kRightLowerArm: return {B::kRightHand};
    case B::kLeftUpperLeg: return {B::kLeftLowerLeg};
    case B::kLeftLowerLeg: return {B::kLeftFoot};
    case B::kLeftFoot: return {B::kLeftToes};
    case B::kRightUpperLeg: return {B::kRightLowerLeg};
    case B::kRightLowerLeg: return {B::kRightFoot};
    case B::kRightFoot: return {B::kRightToes};
    default: return {};
  }
}

struct RestGeometry {
  std::vector<Vector3d> positions;
  std::vector<Quaterniond> rotations;
};

// The bone's direction at rest, in world axes: towards the next mapped bone, else its own
// children, else along its canonical parent's direction. nullopt when nothing shows it.
std::optional<Vector3d> RestDirection(const Skeleton& skeleton, const RigMapping& mapping, const RestGeometry& rest,
                                      HumanoidBone bone, int depth = 0) {
  const int j = mapping.joint(bone);
  for (HumanoidBone next : DirectionBones(bone)) {
    if (!mapping.has(next)) continue;
    const Vector3d d = rest.positions[mapping.joint(next)] - rest.positions[j];
    if (d.norm() >= kMinSegmentM) return d.normalized();
  }
  if (const auto target = ChildTarget(skeleton, j, rest.positions, rest.rotations)) {
    const Vector3d d = *target - rest.positions[j];
    if (d.norm() >= kMinSegmentM) return d.normalized();
  }
  const auto parent = CanonicalParent(bone);
  if (!parent || depth > 4) return std::nullopt;
  for (auto p = parent; p; p = CanonicalParent(*p))
    if (mapping.has(*p) && *p != HumanoidBone::kHips) return RestDirection(skeleton, mapping, rest, *p, depth + 1);
  return std::nullopt;
}

// The hips' height over the feet with the legs straight: the drop from the hips to the
// upper legs plus the thigh and shin lengths (mean of the sides). Bone lengths do not change
// with the pose, so two rests of one rig (a captured mean pose, a database's) agree, where
// the height of a posed rest would follow its knee bend into the root's scale. Without a
// full leg: the rest's hips above its lowest leg joint.
double HipHeight(const RigMapping& mapping, const RestGeometry& rest) {
  const auto at = [&](B b) { return rest.positions[mapping.joint(b)]; };
  double sum = 0.0;
  int sides = 0;
  for (auto [upper, lower, foot] : {std::array{B::kLeftUpperLeg, B::kLeftLowerLeg, B::kLeftFoot},
                                    std::array{B::kRightUpperLeg, B::kRightLowerLeg, B::kRightFoot}}) {
    if (!mapping.has(upper) || !mapping.has(lower) || !mapping.has(foot)) continue;
    sum += at(B::kHips).y() - at(upper).y() + (at(lower) - at(upper)).norm() + (at(foot) - at(lower)).norm();
    ++sides;
  }
  if (sides > 0) return sum / sides;
  const double hips_y = at(B::kHips).y();
  double lowest = hips_y;
  for (B b : {B::kLeftFoot, B::kRightFoot, B::kLeftToes, B::kRightToes, B::kLeftLowerLeg, B::kRightLowerLeg})
    if (mapping.has(b)) lowest = std::min(lowest, at(b).y());
  return hips_y - lowest;
}

void ForwardKinematics(const Skeleton& skeleton, const std::vector<Quaterniond>& local_rotations,
                       const std::vector<Vector3d>& local_translations, std::vector<Vector3d>& positions,
                       std::vector<Quaterniond>& rotations) {
  const int n = skeleton.num_joints();
  positions.resize(n);
  rotations.resize(n);
  for (int j = 0; j < n; ++j) {
    const int p = skeleton.parent(j);
    if (p == kNoParent) {
      positions[j] = local_translations[j];
      rotations[j] = local_rotations[j];
    } else {
      positions[j] = positions[p] + rotations[p] * skeleton.joint(p).rest_scale.cwiseProduct(local_translations[j]);
      rotations[j] = rotations[p] * local_rotations[j];
    }
  }
}

Quaterniond Power(const Quaterniond& q, double s) {
  Quaterniond shortest = q.w() < 0 ? Quaterniond(-q.w(), -q.x(), -q.y(), -q.z()) : q;
  return Quaterniond::Identity().slerp(s, shortest);
}

constexpr std::array<HumanoidBone, 5> kTorsoOrder = {HumanoidBone::kSpine, HumanoidBone::kChest,
                                                      HumanoidBone::kUpperChest, HumanoidBone::kNeck,
                                                      HumanoidBone::kHead};

// Per rig joint: the canonical bone it carries in this transfer, or -1. Torso bones of the
// rig that the motion lacks (an upperChest, a chest) are carried too, with rotations
// interpolated from the torso bones around them (TorsoRotations).
std::vector<int> EffectiveBones(const HumanoidRig& rig, const CanonicalMotion& motion) {
  std::vector<int> bone_of(rig.skeleton().num_joints(), -1);
  bool any_torso = false;
  for (HumanoidBone b : kTorsoOrder) any_torso = any_torso || motion.present[BoneIndex(b)];
  for (int b = 0; b < kNumHumanoidBones; ++b)
    if (rig.mapping().joints[b] >= 0 && (motion.present[b] || (any_torso && IsTorso(BoneAt(b)))))
      bone_of[rig.mapping().joints[b]] = b;
  return bone_of;
}

// Frame f's canonical rotations, with missing torso bones halfway between the nearest
// present torso bones below and above them (the end one held where only one side exists).
std::array<Quaterniond, kNumHumanoidBones> FrameRotations(const CanonicalMotion& motion, int f) {
  std::array<Quaterniond, kNumHumanoidBones> g;
  for (int b = 0; b < kNumHumanoidBones; ++b) g[b] = motion.rotation(f, BoneAt(b));
  const int n = static_cast<int>(kTorsoOrder.size());
  for (int i = 0; i < n; ++i) {
    const int b = BoneIndex(kTorsoOrder[i]);
    if (motion.present[b]) continue;
    int below = -1, above = -1;
    for (int k = i - 1; k >= 0 && below < 0; --k)
      if (motion.present[BoneIndex(kTorsoOrder[k])]) below = BoneIndex(kTorsoOrder[k]);
    for (int k = i + 1; k < n && above < 0; ++k)
      if (motion.present[BoneIndex(kTorsoOrder[k])]) above = BoneIndex(kTorsoOrder[k]);
    if (below < 0) below = BoneIndex(HumanoidBone::kHips);
    g[b] = above >= 0 ? g[below].slerp(0.5, g[above]).normalized() : g[below];
  }
  return g;
}

// The torso chain between joint j (a torso bone) and its nearest ancestor that carries a
// bone: the joints in between, top first, and that ancestor (-1 when none).
std::vector<int> ChainAbove(const Skeleton& skeleton, const std::vector<int>& bone_of, int j, int& anchor) {
  std::vector<int> between;
  anchor = -1;
  for (int p = skeleton.parent(j); p != kNoParent; p = skeleton.parent(p)) {
    if (bone_of[p] >= 0) {
      anchor = p;
      break;
    }
    between.push_back(p);
  }
  std::reverse(between.begin(), between.end());
  if (anchor < 0) between.clear();
  return between;
}

// Position of `end` relative to the chain's anchor, the anchor at world rotation
// `anchor_world`, through `middle` at frame f's local transforms.
Vector3d ChainEnd(const Skeleton& skeleton, const MotionClip& clip, int f, const std::vector<int>& middle, int end,
                  const Quaterniond& anchor_world) {
  Vector3d position = Vector3d::Zero();
  Quaterniond world = anchor_world;
  int parent = skeleton.parent(middle.front());
  for (size_t m = 0; m <= middle.size(); ++m) {
    const int j = m < middle.size() ? middle[m] : end;
    position += world * skeleton.joint(parent).rest_scale.cwiseProduct(clip.translation(f, j));
    world = world * clip.rotation(f, j);
    parent = j;
  }
  return position;
}

}  // namespace

Result<HumanoidRig> HumanoidRig::Make(const Skeleton& skeleton, const RigMapping& mapping, const RigRest& rest) {
  const int n = skeleton.num_joints();
  if (static_cast<int>(rest.local_rotations.size()) != n || static_cast<int>(rest.local_translations.size()) != n)
    return InvalidData("the rest pose does not fit the skeleton (" + std::to_string(rest.local_rotations.size()) +
                       " joints for " + std::to_string(n) + ")");
  for (B b : {B::kHips, B::kLeftUpperLeg, B::kRightUpperLeg})
    if (!mapping.has(b)) return InvalidData(std::string("the rig has no ") + HumanoidBoneName(b));
  HumanoidRig rig;
  rig.skeleton_ = skeleton;
  rig.mapping_ = mapping;
  rig.rest_ = rest;
  RestGeometry g;
  ForwardKinematics(skeleton, rest.local_rotations, rest.local_translations, g.positions, g.rotations);

  // The rig's own axes: up is the imported +Y; left from the hips and shoulder joints.
  const auto at = [&](B b) { return g.positions[mapping.joint(b)]; };
  Vector3d lateral = at(B::kLeftUpperLeg) - at(B::kRightUpperLeg);
  if (mapping.has(B::kLeftUpperArm) && mapping.has(B::kRightUpperArm))
    lateral += at(B::kLeftUpperArm) - at(B::kRightUpperArm);
  lateral.y() = 0.0;
  if (lateral.norm() < kMinSegmentM)
    return InvalidData("the rest pose shows no left-right extent (left and right hips coincide seen from above)");
  const Vector3d left = lateral.normalized(), up = Vector3d::UnitY(), forward = left.cross(up);
  Matrix3d axes;
  axes.col(0) = left;
  axes.col(1) = up;
  axes.col(2) = forward;
  rig.frame_ = Quaterniond(axes);
  const Quaterniond to_canonical = rig.frame_.conjugate();

  rig.hip_height_m_ = HipHeight(mapping, g);
  if (rig.hip_height_m_ < 1e-3) return InvalidData("the rest pose has the feet as high as the hips");

  for (int b = 0; b < kNumHumanoidBones; ++b) {
    rig.t_pose_[b] = Quaterniond::Identity();
    rig.aim_joint_[b] = -1;
  }
  // The T-pose is built down the hierarchy: each mapped joint is first carried rigidly with
  // the correction that straightened its nearest mapped ancestor, then swung the shortest
  // way so that its bone points in the canonical direction. A bone's twist in the T-pose is
  // therefore its twist relative to its parent in the rest, whatever the parent's pose: two
  // rests of one rig that differ in a turn of the hips give the same leg twists, where a
  // twist measured against world axes (Frame with a fixed reference per bone) carries the
  // turn into every bone below it.
  std::vector<Quaterniond> correction(n, Quaterniond::Identity());
  for (int j = 0; j < n; ++j) {
    const int b = mapping.BoneOfJoint(j);
    if (b < 0) continue;
    const B bone = BoneAt(b);
    for (HumanoidBone next : DirectionBones(bone)) {
      if (!mapping.has(next)) continue;
      if ((g.positions[mapping.joint(next)] - g.positions[j]).norm() < kMinSegmentM) continue;
      // Aim only across joints no canonical bone names (CMU's Neck1); through a mapped bone
      // (Spine1 -> Neck -> Neck1 -> Head, where Neck sits on Spine1) the line is that
      // bone's business.
      bool only_unmapped = true;
      for (int p = skeleton.parent(mapping.joint(next)); p != j && p != kNoParent; p = skeleton.parent(p))
        only_unmapped = only_unmapped && mapping.BoneOfJoint(p) < 0;
      if (skeleton.parent(mapping.joint(next)) != j && only_unmapped) rig.aim_joint_[b] = mapping.joint(next);
      break;
    }
    if (bone == B::kHips) {
      // The pelvis is placed by its left-right axis and the world up.
      const Vector3d hips_lateral = to_canonical * (at(B::kLeftUpperLeg) - at(B::kRightUpperLeg));
      const Matrix3d rest_frame = Frame(hips_lateral, Vector3d::UnitY());
      const Matrix3d canonical_frame = Frame(Vector3d::UnitX(), Vector3d::UnitY());
      correction[j] = Quaterniond(Matrix3d(canonical_frame * rest_frame.transpose()));
    } else {
      int ancestor = skeleton.parent(j);
      while (ancestor != kNoParent && mapping.BoneOfJoint(ancestor) < 0) ancestor = skeleton.parent(ancestor);
      const Quaterniond carried = ancestor == kNoParent ? Quaterniond::Identity() : correction[ancestor];
      const auto dir = RestDirection(skeleton, mapping, g, bone);
      const Vector3d d = dir ? Vector3d(carried * (to_canonical * *dir)) : CanonicalDirection(bone);
      correction[j] = (Quaterniond::FromTwoVectors(d, CanonicalDirection(bone)) * carried).normalized();
    }
    rig.t_pose_[b] = (correction[j] * to_canonical * g.rotations[j]).normalized();
  }
  return rig;
}

CanonicalMotion ToCanonical(const HumanoidRig& rig, const MotionClip& clip) {
  CanonicalMotion m;
  m.sample_rate_hz = clip.sample_rate_hz;
  m.num_frames = clip.num_frames;
  m.rotations.assign(static_cast<size_t>(clip.num_frames) * kNumHumanoidBones, Quaterniond::Identity());
  m.hips.assign(clip.num_frames, Vector3d::Zero());
  const RigMapping& mapping = rig.mapping();
  for (int b = 0; b < kNumHumanoidBones; ++b) {
    const int j = mapping.joints[b];
    m.present[b] = j >= 0;
    if (j >= 0 && j < static_cast<int>(clip.keys.size())) m.keys[b] = clip.keys[j];
  }
  const Quaterniond to_canonical = rig.frame().conjugate();
  const int hips = mapping.joint(HumanoidBone::kHips);
  WorldPose pose;
  for (int f = 0; f < clip.num_frames; ++f) {
    ComputeWorldPose(rig.skeleton(), clip, f, pose);
    for (int b = 0; b < kNumHumanoidBones; ++b) {
      if (!m.present[b]) continue;
      const int j = mapping.joints[b];
      Quaterniond g = to_canonical * pose.rotations[j] * rig.t_pose_rotation(BoneAt(b)).conjugate();
      // A bone spanning several joints points where its chain ends, not where its first
      // joint alone would take it: the swing between the two is the chain's own bend.
      if (const int aim = rig.aim_joint(BoneAt(b)); aim >= 0) {
        const Vector3d actual = to_canonical * (pose.positions[aim] - pose.positions[j]);
        g = Quaterniond::FromTwoVectors(g * CanonicalDirection(BoneAt(b)), actual) * g;
      }
      m.rotations[static_cast<size_t>(f) * kNumHumanoidBones + b] = g.normalized();
    }
    m.hips[f] = (to_canonical * pose.positions[hips]) / rig.hip_height_m();
  }
  // Hemisphere continuity per bone keeps later interpolation on the short arc.
  for (int b = 0; b < kNumHumanoidBones; ++b)
    MakeHemisphereContinuous(m.rotations, b, m.num_frames, kNumHumanoidBones);
  return m;
}

MotionClip FromCanonical(const HumanoidRig& rig, const CanonicalMotion& motion, const MotionClip* base) {
  const Skeleton& skeleton = rig.skeleton();
  const int n = skeleton.num_joints();
  MotionClip out;
  if (base) {
    out = *base;
  } else {
    out = MotionClip::RestPose(skeleton, motion.num_frames, motion.sample_rate_hz);
    for (int f = 0; f < motion.num_frames; ++f)
      for (int j = 0; j < n; ++j) {
        out.rotation(f, j) = rig.rest().local_rotations[j];
        out.translation(f, j) = rig.rest().local_translations[j];
      }
  }
  out.sample_rate_hz = motion.sample_rate_hz;
  const std::vector<int> bone_of = EffectiveBones(rig, motion);
  const int hips = rig.mapping().joint(HumanoidBone::kHips);
  const Quaterniond frame = rig.frame();

  // Torso chains whose middle joints share the rotation between the bones around them.
  std::vector<std::vector<int>> chains(n);
  std::vector<int> anchors(n, -1);
  std::vector<std::uint8_t> claimed(n, 0);
  for (int j = 0; j < n; ++j) {
    if (bone_of[j] < 0 || !IsTorso(BoneAt(bone_of[j]))) continue;
    chains[j] = ChainAbove(skeleton, bone_of, j, anchors[j]);
    std::erase_if(chains[j], [&](int i) { return claimed[i]; });
    for (int i : chains[j]) claimed[i] = 1;
  }

  std::vector<Quaterniond> desired(n), world_rot(n);
  std::vector<Vector3d> world_pos(n);
  for (int f = 0; f < out.num_frames; ++f) {
    const std::array<Quaterniond, kNumHumanoidBones> g = FrameRotations(motion, f);
    for (int j = 0; j < n; ++j)
      if (bone_of[j] >= 0) desired[j] = frame * g[bone_of[j]] * rig.t_pose_rotation(BoneAt(bone_of[j]));
    // Spread each torso bone's rotation relative to its anchor over the joints between them:
    // the chain's cumulative rotation at step m is E^(m/n) times its base rotation.
    for (int j = 0; j < n; ++j) {
      if (chains[j].empty()) continue;
      Quaterniond base_product = Quaterniond::Identity();
      for (int i : chains[j]) base_product = base_product * out.rotation(f, i);
      const Quaterniond whole_base = base_product * out.rotation(f, j);
      const Quaterniond wanted = desired[anchors[j]].conjugate() * desired[j];
      const Quaterniond spread = wanted * whole_base.conjugate();
      const double steps = static_cast<double>(chains[j].size() + 1);
      const Vector3d rigid_end = ChainEnd(skeleton, out, f, chains[j], j, desired[anchors[j]]);
      Quaterniond previous = Quaterniond::Identity(), running_base = Quaterniond::Identity();
      for (size_t m = 0; m < chains[j].size(); ++m) {
        running_base = running_base * out.rotation(f, chains[j][m]);
        const Quaterniond cumulative = Power(spread, (m + 1) / steps) * running_base;
        out.rotation(f, chains[j][m]) = (previous.conjugate() * cumulative).normalized();
        previous = cumulative;
      }
      // Spreading bends the chain, which would move the bone's end off its direction; one
      // turn of the first middle joint puts it back where the unbent chain had it, so the
      // bone's direction (anchor to bone joint) stays exact and the twist stays spread.
      const int first = chains[j].front();
      const Vector3d first_pos = desired[anchors[j]] * skeleton.joint(anchors[j]).rest_scale.cwiseProduct(
                                                            out.translation(f, first));
      const Vector3d spread_end = ChainEnd(skeleton, out, f, chains[j], j, desired[anchors[j]]);
      const Quaterniond aim = Quaterniond::FromTwoVectors(spread_end - first_pos, rigid_end - first_pos);
      const Quaterniond first_world = desired[anchors[j]] * out.rotation(f, first);
      out.rotation(f, first) = (desired[anchors[j]].conjugate() * aim * first_world).normalized();
    }
    for (int j = 0; j < n; ++j) {
      const int p = skeleton.parent(j);
      const Quaterniond parent_rot = p == kNoParent ? Quaterniond::Identity() : world_rot[p];
      const Vector3d parent_pos = p == kNoParent ? Vector3d::Zero() : world_pos[p];
      const Vector3d parent_scale = p == kNoParent ? Vector3d::Ones() : skeleton.joint(p).rest_scale;
      if (bone_of[j] >= 0) out.rotation(f, j) = (parent_rot.conjugate() * desired[j]).normalized();
      if (j == hips) {
        const Vector3d target = frame * (motion.hips[f] * rig.hip_height_m());
        out.translation(f, j) = (parent_rot.conjugate() * (target - parent_pos)).cwiseQuotient(parent_scale);
      }
      world_rot[j] = parent_rot * out.rotation(f, j);
      world_pos[j] = parent_pos + parent_rot * parent_scale.cwiseProduct(out.translation(f, j));
    }
  }
  if (out.keys.size() != static_cast<size_t>(n)) out.keys.assign(n, JointKeys{});
  for (int j = 0; j < n; ++j) {
    if (bone_of[j] < 0) continue;
    const JointKeys& k = motion.keys[bone_of[j]];
    out.keys[j].rotation_frames = k.rotation_frames;
    if (j == hips) out.keys[j].translation_frames = k.translation_frames;
  }
  out.translation_animated.resize(n, 0);
  out.translation_animated[hips] = 1;
  out.MakeContinuous();
  return out;
}

MotionClip RetargetClip(const HumanoidRig& from, const MotionClip& clip, const HumanoidRig& to) {
  MotionClip out = FromCanonical(to, ToCanonical(from, clip));
  out.name = clip.name;
  return out;
}

bool SameRig(const Skeleton& a, const Skeleton& b, const std::vector<std::uint8_t>& translating) {
  if (a.num_joints() != b.num_joints()) return false;
  for (int j = 0; j < a.num_joints(); ++j) {
    if (a.name(j) != b.name(j) || a.parent(j) != b.parent(j)) return false;
    if (j < static_cast<int>(translating.size()) && translating[j]) continue;
    const Vector3d& ta = a.joint(j).rest_translation;
    const Vector3d& tb = b.joint(j).rest_translation;
    const bool za = ta.norm() < kMinSegmentM, zb = tb.norm() < kMinSegmentM;
    if (za != zb) return false;
    if (!za && ta.normalized().dot(tb.normalized()) < 1.0 - 1e-6) return false;
    if (a.joint(j).rest_rotation.angularDistance(b.joint(j).rest_rotation) > 1e-6) return false;
  }
  return true;
}

}  // namespace mocapfill
