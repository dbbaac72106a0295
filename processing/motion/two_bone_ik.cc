#include "processing/motion/two_bone_ik.h"

#include <algorithm>
#include <cmath>

namespace mocapfill {

namespace {

using Eigen::AngleAxisd;
using Eigen::Quaterniond;
using Eigen::Vector3d;

Quaterniond ParentWorld(const Skeleton& skeleton, const WorldPose& pose, int joint) {
  const int parent = skeleton.parent(joint);
  return parent == kNoParent ? Quaterniond::Identity() : pose.rotations[parent];
}

}  // namespace

TwoBoneSolution SolveTwoBoneIk(const Skeleton& skeleton, const WorldPose& pose, const TwoBoneChain& chain,
                               const Vector3d& target) {
  const Vector3d a = pose.positions[chain.upper], b = pose.positions[chain.lower], c = pose.positions[chain.end];
  const double upper_length = (b - a).norm(), lower_length = (c - b).norm();
  // Never fully straight or folded: the bend plane must stay defined for the next solve.
  const double slack = 1e-6 * (upper_length + lower_length);
  const double span = std::clamp((target - a).norm(), std::abs(upper_length - lower_length) + slack,
                                 upper_length + lower_length - slack);

  // Bend at the middle joint, about the normal of the plane the chain lies in.
  const Vector3d to_upper = a - b, to_end = c - b;
  Vector3d axis = to_upper.cross(to_end);
  if (axis.norm() < 1e-9 * std::max(1e-12, upper_length * lower_length)) axis = to_upper.unitOrthogonal();
  axis.normalize();
  const double current = std::atan2(to_upper.cross(to_end).dot(axis), to_upper.dot(to_end));
  const double wanted = std::acos(std::clamp(
      (upper_length * upper_length + lower_length * lower_length - span * span) / (2.0 * upper_length * lower_length),
      -1.0, 1.0));
  // Turning the end about `axis` by a positive angle carries it away from the upper joint.
  const Quaterniond bend(AngleAxisd(wanted - current, axis));
  const Vector3d bent_end = b + bend * (c - b);
  const Quaterniond aim = Quaterniond::FromTwoVectors(bent_end - a, target - a);

  TwoBoneSolution out;
  const Quaterniond upper_world = aim * pose.rotations[chain.upper];
  const Quaterniond lower_parent_world = aim * ParentWorld(skeleton, pose, chain.lower);
  const Quaterniond lower_world = aim * bend * pose.rotations[chain.lower];
  const Quaterniond end_parent_world = aim * bend * ParentWorld(skeleton, pose, chain.end);
  out.upper = (ParentWorld(skeleton, pose, chain.upper).conjugate() * upper_world).normalized();
  out.lower = (lower_parent_world.conjugate() * lower_world).normalized();
  out.end = (end_parent_world.conjugate() * pose.rotations[chain.end]).normalized();
  out.miss_m = std::abs((target - a).norm() - span);
  return out;
}

}  // namespace mocapfill
