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

Vector3d HingeOf(const Skeleton& skeleton, const MotionClip& clip, const TwoBoneChain& chain) {
  WorldPose pose;
  Vector3d hinge = Vector3d::Zero();
  double most = 0.0;
  for (int f = 0; f < clip.num_frames; ++f) {
    ComputeWorldPose(skeleton, clip, f, pose);
    const Vector3d to_upper = pose.positions[chain.upper] - pose.positions[chain.lower];
    const Vector3d to_end = pose.positions[chain.end] - pose.positions[chain.lower];
    const Vector3d normal = to_upper.cross(to_end);
    const double bend = std::atan2(normal.norm(), to_upper.dot(to_end));  // interior angle
    const double turn = 3.14159265358979323846 - bend;                    // away from straight
    if (turn > most && normal.norm() > 0) {
      most = turn;
      hinge = pose.rotations[chain.upper].conjugate() * normal.normalized();
    }
  }
  return hinge;
}

TwoBoneSolution SolveTwoBoneIk(const Skeleton& skeleton, const WorldPose& pose, const TwoBoneChain& chain,
                               const Vector3d& target, const Vector3d& hinge) {
  const Vector3d a = pose.positions[chain.upper], b = pose.positions[chain.lower], c = pose.positions[chain.end];
  const double upper_length = (b - a).norm(), lower_length = (c - b).norm();
  // Never fully straight or folded: the bend plane must stay defined for the next solve.
  const double slack = 1e-6 * (upper_length + lower_length);
  const double span = std::clamp((target - a).norm(), std::abs(upper_length - lower_length) + slack,
                                 upper_length + lower_length - slack);

  // Bend at the middle joint about `axis`, by the angle that makes the chain span the distance
  // to the target. With u = a - b and v = c - b split along the axis and across it,
  // |u - R v|^2 = |u|^2 + |v|^2 - 2 u.v (along) - 2 |u across| |v across| cos(angle across),
  // which gives the angle across; the bend keeps its sense about the axis (forward for a knee).
  const Vector3d to_upper = a - b, to_end = c - b;
  Vector3d axis = hinge.squaredNorm() > 0 ? Vector3d(pose.rotations[chain.upper] * hinge) : to_upper.cross(to_end);
  if (axis.norm() < 1e-9 * std::max(1e-12, upper_length * lower_length)) axis = to_upper.unitOrthogonal();
  axis.normalize();
  const Vector3d u_across = to_upper - to_upper.dot(axis) * axis, v_across = to_end - to_end.dot(axis) * axis;
  const double across = std::max(1e-12, 2.0 * u_across.norm() * v_across.norm());
  const double cos_angle = (to_upper.squaredNorm() + to_end.squaredNorm() - 2.0 * to_upper.dot(axis) * to_end.dot(axis) -
                            span * span) / across;
  const double wanted = std::acos(std::clamp(cos_angle, -1.0, 1.0));
  const double current = std::atan2(u_across.cross(v_across).dot(axis), u_across.dot(v_across));
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
  out.miss_m = std::abs((target - a).norm() - (bent_end - a).norm());
  return out;
}

}  // namespace mocapfill
