#include "processing/synthesis/limb_reach.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "processing/retargeting/rig_mapping.h"

namespace mocapfill {

using Eigen::Quaterniond;
using Eigen::Vector3d;

std::vector<Limb> ArmsOf(const Skeleton& skeleton) {
  Result<RigMapping> mapping = MapHumanoid(skeleton, {});
  if (!mapping.ok()) return {};
  using B = HumanoidBone;
  std::vector<Limb> arms;
  for (const auto& bones : {std::array{B::kLeftUpperArm, B::kLeftLowerArm, B::kLeftHand},
                            std::array{B::kRightUpperArm, B::kRightLowerArm, B::kRightHand}}) {
    const Limb arm{mapping->joint(bones[0]), mapping->joint(bones[1]), mapping->joint(bones[2])};
    if (arm.upper < 0 || arm.lower < 0 || arm.end < 0) continue;
    if (skeleton.parent(arm.lower) != arm.upper || skeleton.parent(arm.end) != arm.lower) continue;
    arms.push_back(arm);
  }
  return arms;
}

std::vector<int> LimbsWithin(const std::vector<Limb>& limbs, const std::vector<int>& joints) {
  auto in = [&](int j) { return std::find(joints.begin(), joints.end(), j) != joints.end(); };
  std::vector<int> within;
  for (size_t i = 0; i < limbs.size(); ++i)
    if (in(limbs[i].upper) && in(limbs[i].lower) && in(limbs[i].end)) within.push_back(static_cast<int>(i));
  return within;
}

ArmReach PrepareArmReach(const MotionDatabase& db) {
  const Skeleton& s = db.skeleton();
  const Eigen::MatrixXf& signals = db.signals();
  ArmReach r{ArmsOf(s), {}, Eigen::MatrixXf(signals.rows(), 0)};
  r.table.resize(signals.rows(), 3 * r.arms.size());
  for (size_t i = 0; i < r.arms.size(); ++i) {
    const Limb& arm = r.arms[i];
    const Vector3d b1 = RestOffset(s, arm.lower), b2 = RestOffset(s, arm.end);
    // The elbow's axis: the bend plane's normal where the database bends the arm most (a
    // nearly straight arm shows no plane of its own).
    Vector3d hinge = Vector3d::UnitX();
    double most = 0.0;
    for (int f = 0; f < signals.rows(); ++f) {
      const Quaterniond q1 = db.LocalRotation(arm.upper, signals.row(f).segment<3>(3 * arm.upper).cast<double>());
      const Quaterniond q2 = db.LocalRotation(arm.lower, signals.row(f).segment<3>(3 * arm.lower).cast<double>());
      const Vector3d forearm = q2 * b2, n = b1.cross(forearm);
      if (n.norm() > most) {
        most = n.norm();
        hinge = n.normalized();
      }
      r.table.row(f).segment<3>(3 * i) = (q1 * (b1 + forearm)).cast<float>();
    }
    r.hinges.push_back(hinge);
  }
  return r;
}

void ReachLimbs(const MotionDatabase& db, const ArmReach& prepared, const std::vector<int>& which,
                const Eigen::MatrixXd& reach, double strength, Eigen::MatrixXd& out) {
  const Skeleton& s = db.skeleton();
  for (int i : which) {
    const Limb& limb = prepared.arms[i];
    const Vector3d upper_bone = RestOffset(s, limb.lower), lower_bone = RestOffset(s, limb.end);
    const double l1 = upper_bone.norm(), l2 = lower_bone.norm();
    if (l1 <= 0.0 || l2 <= 0.0) continue;
    for (int f = 0; f < out.rows(); ++f) {
      const Quaterniond q1 = db.LocalRotation(limb.upper, out.row(f).segment<3>(3 * limb.upper).transpose());
      const Quaterniond q2 = db.LocalRotation(limb.lower, out.row(f).segment<3>(3 * limb.lower).transpose());
      const Vector3d elbow = q1 * upper_bone, forearm = q1 * (q2 * lower_bone);
      const Vector3d tip = elbow + forearm;
      Vector3d target = tip + strength * (reach.row(f).segment<3>(3 * i).transpose() - tip);
      // Out of the limb's reach, or folded onto itself: the nearest reachable distance. (A target
      // between two reachable points, as blends of captured hands are, is reachable.)
      const double d = std::clamp(target.norm(), std::abs(l1 - l2) + 1e-3 * (l1 + l2), l1 + l2);
      if (!(target.norm() > 0.0)) continue;
      target *= d / target.norm();
      // Bend about the hinge through the elbow until the tip is at distance d from the shoulder.
      const Vector3d n = q1 * prepared.hinges[i];
      const Vector3d e_perp = elbow - elbow.dot(n) * n, w_perp = forearm - forearm.dot(n) * n;
      const double pe = e_perp.norm(), pw = w_perp.norm();
      if (pe < 1e-9 || pw < 1e-9) continue;
      const double along = elbow.dot(n) * forearm.dot(n);
      const double c = std::clamp(((d * d - l1 * l1 - l2 * l2) / 2.0 - along) / (pe * pw), -1.0, 1.0);
      const double theta0 = std::atan2(e_perp.cross(w_perp).dot(n), e_perp.dot(w_perp));
      // Always on the elbow's own side of the hinge: choosing the side nearer the blend's own
      // bend would flip the elbow through straight between two frames where the blend passes
      // straight (an arm blended a little past straight is bent back to its side).
      const double theta = std::acos(c);
      const Quaterniond bend(Eigen::AngleAxisd(theta - theta0, n));
      const Vector3d bent = elbow + bend * forearm;
      const Quaterniond swing = Quaterniond::FromTwoVectors(bent, target);
      const Quaterniond new_q1 = swing * q1, new_q2 = q1.conjugate() * bend * q1 * q2;
      out.row(f).segment<3>(3 * limb.upper) = LogMap(db.joint_means()[limb.upper].conjugate() * new_q1).transpose();
      out.row(f).segment<3>(3 * limb.lower) = LogMap(db.joint_means()[limb.lower].conjugate() * new_q2).transpose();
    }
  }
}

}  // namespace mocapfill
