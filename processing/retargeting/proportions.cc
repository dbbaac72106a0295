#include "processing/retargeting/proportions.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mocapfill {

namespace {

using B = HumanoidBone;

// Mean over the sides mapped of |a-b| + |b-c|.
double LimbLength(const RigMapping& m, const std::vector<Eigen::Vector3d>& p, B a, B b, B c) {
  double sum = 0;
  int sides = 0;
  for (bool mirrored : {false, true}) {
    const B x = mirrored ? MirrorBone(a) : a, y = mirrored ? MirrorBone(b) : b, z = mirrored ? MirrorBone(c) : c;
    if (m.joint(x) < 0 || m.joint(y) < 0 || m.joint(z) < 0) continue;
    sum += (p[m.joint(y)] - p[m.joint(x)]).norm() + (p[m.joint(z)] - p[m.joint(y)]).norm();
    ++sides;
  }
  return sides ? sum / sides : 0;
}

}  // namespace

RigProportions MeasureProportions(const Skeleton& skeleton, const RigMapping& m, const RigRest& rest) {
  const std::vector<Eigen::Vector3d> p = rest.WorldPositions(skeleton);
  RigProportions out;
  double floor = std::numeric_limits<double>::infinity();
  for (B b : {B::kLeftFoot, B::kRightFoot, B::kLeftToes, B::kRightToes})
    if (m.joint(b) >= 0) floor = std::min(floor, p[m.joint(b)].y());
  if (m.has(B::kHips) && std::isfinite(floor)) out.hip_height = p[m.joint(B::kHips)].y() - floor;
  out.leg_length = LimbLength(m, p, B::kLeftUpperLeg, B::kLeftLowerLeg, B::kLeftFoot);
  out.arm_length = LimbLength(m, p, B::kLeftUpperArm, B::kLeftLowerArm, B::kLeftHand);
  if (m.has(B::kHead) && std::isfinite(floor)) {
    // The top of the head: the highest joint (or BVH end site) at or below the head joint.
    double top = p[m.joint(B::kHead)].y();
    const std::vector<Eigen::Quaterniond> r = rest.WorldRotations(skeleton);
    for (int j = 0; j < skeleton.num_joints(); ++j) {
      bool under_head = false;
      for (int k = j; k != kNoParent; k = skeleton.parent(k)) under_head |= k == m.joint(B::kHead);
      if (!under_head) continue;
      top = std::max(top, p[j].y());
      if (skeleton.joint(j).end_site) top = std::max(top, (p[j] + r[j] * *skeleton.joint(j).end_site).y());
    }
    out.height = top - floor;
  }
  return out;
}

}  // namespace mocapfill
