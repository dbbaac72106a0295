#include "tests/support/bone_directions.h"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"

namespace mocapfill::testing {

namespace {

using B = HumanoidBone;

Eigen::Vector3d Direction(const HumanoidRig& rig, const WorldPose& pose, const BoneSegment& s) {
  const RigMapping& m = rig.mapping();
  const Eigen::Vector3d d = pose.positions[m.joint(s.second)] - pose.positions[m.joint(s.first)];
  const int hips = m.joint(B::kHips);
  // The hips' canonical rotation: world rotation relative to its T-pose, in canonical axes.
  const Eigen::Quaterniond to_canonical = rig.frame().conjugate();
  const Eigen::Quaterniond hips_c = to_canonical * pose.rotations[hips] * rig.t_pose_rotation(B::kHips).conjugate();
  return (hips_c.conjugate() * (to_canonical * d)).normalized();
}

}  // namespace

std::vector<BoneSegment> UpperBodySegments() {
  return {{B::kHips, B::kNeck},          {B::kNeck, B::kHead},
          {B::kLeftShoulder, B::kLeftUpperArm}, {B::kRightShoulder, B::kRightUpperArm},
          {B::kLeftUpperArm, B::kLeftLowerArm}, {B::kRightUpperArm, B::kRightLowerArm},
          {B::kLeftLowerArm, B::kLeftHand},     {B::kRightLowerArm, B::kRightHand}};
}

std::vector<BoneSegment> LimbSegments() {
  std::vector<BoneSegment> s = UpperBodySegments();
  s.erase(s.begin());  // the trunk spans several bones
  const std::vector<BoneSegment> legs = {{B::kLeftUpperLeg, B::kLeftLowerLeg}, {B::kRightUpperLeg, B::kRightLowerLeg},
                                         {B::kLeftLowerLeg, B::kLeftFoot},     {B::kRightLowerLeg, B::kRightFoot},
                                         {B::kLeftFoot, B::kLeftToes},         {B::kRightFoot, B::kRightToes}};
  s.insert(s.end(), legs.begin(), legs.end());
  return s;
}

std::vector<BoneSegment> BoneSegments(const RigMapping& rig) {
  std::vector<BoneSegment> s;
  HumanoidBone previous = B::kHips;
  for (B b : {B::kSpine, B::kChest, B::kUpperChest, B::kNeck}) {
    if (!rig.has(b)) continue;
    if (previous != B::kHips) s.push_back({previous, b});
    previous = b;
  }
  for (const BoneSegment& limb : LimbSegments()) s.push_back(limb);
  return s;
}

std::vector<double> DirectionErrorsDeg(const HumanoidRig& a, const MotionClip& clip_a, const HumanoidRig& b,
                                       const MotionClip& clip_b, const std::vector<BoneSegment>& segments) {
  std::vector<BoneSegment> used;
  for (const BoneSegment& s : segments)
    if (a.mapping().has(s.first) && a.mapping().has(s.second) && b.mapping().has(s.first) &&
        b.mapping().has(s.second))
      used.push_back(s);
  std::vector<double> errors;
  WorldPose pa, pb;
  for (int f = 0; f < std::min(clip_a.num_frames, clip_b.num_frames); ++f) {
    ComputeWorldPose(a.skeleton(), clip_a, f, pa);
    ComputeWorldPose(b.skeleton(), clip_b, f, pb);
    for (const BoneSegment& s : used) {
      const double c = std::clamp(Direction(a, pa, s).dot(Direction(b, pb, s)), -1.0, 1.0);
      errors.push_back(std::acos(c) * kDegPerRad);
    }
  }
  return errors;
}

double MaxDirectionErrorDeg(const HumanoidRig& a, const MotionClip& clip_a, const HumanoidRig& b,
                            const MotionClip& clip_b, const std::vector<BoneSegment>& segments) {
  const std::vector<double> e = DirectionErrorsDeg(a, clip_a, b, clip_b, segments);
  return e.empty() ? 0.0 : *std::max_element(e.begin(), e.end());
}

double MeanDirectionErrorDeg(const HumanoidRig& a, const MotionClip& clip_a, const HumanoidRig& b,
                             const MotionClip& clip_b, const std::vector<BoneSegment>& segments) {
  const std::vector<double> e = DirectionErrorsDeg(a, clip_a, b, clip_b, segments);
  return e.empty() ? 0.0 : std::accumulate(e.begin(), e.end(), 0.0) / e.size();
}

}  // namespace mocapfill::testing
