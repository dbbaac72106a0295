// Ceres functors for the non-linear key residuals of the key fit (pca_fit.h): geodesic rotation
// keys and keyed joint positions through forward kinematics. Both read a joint's weighted
// tangent channels either from the PCA coefficients of the frame (subspace variant:
// y_j = mu_j + U_j c) or directly from a 3-parameter joint block (full-pose variant).
// Internal: include only from processing/pca/*.cc (used with DynamicAutoDiffCostFunction).
#pragma once

#include <ceres/rotation.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace mocapfill::pca_internal {

// Where the 3 weighted tangent channels of one joint come from, and how they become a
// rotation: R = prefix * mean * Exp(y / weight).
struct JointSource {
  int block = 0;                                  // parameter block index
  Eigen::Matrix<double, 3, Eigen::Dynamic> basis;  // subspace: U_j (3 x K); empty: full-pose block
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // subspace: mu_j
  double weight = 1.0;
  Eigen::Quaterniond mean = Eigen::Quaterniond::Identity();

  // The joint's rotation as a w-first quaternion (Ceres convention).
  template <typename T>
  void Rotation(T const* const* parameters, T q[4]) const {
    const T* x = parameters[block];
    T v[3];
    for (int i = 0; i < 3; ++i) {
      if (basis.cols() == 0) {
        v[i] = x[i];
      } else {
        v[i] = T(offset[i]);
        for (Eigen::Index k = 0; k < basis.cols(); ++k) v[i] += basis(i, k) * x[k];
      }
      v[i] /= T(weight);
    }
    T exp_q[4];
    ceres::AngleAxisToQuaternion(v, exp_q);
    const T mean_q[4] = {T(mean.w()), T(mean.x()), T(mean.y()), T(mean.z())};
    ceres::QuaternionProduct(mean_q, exp_q, q);
  }
};

// Residual Log(R_key^-1 * R(y)) / sigma (3 entries, radians over radians).
struct GeodesicKeyFunctor {
  JointSource joint;
  Eigen::Quaterniond key_inverse;
  double inv_sigma_rad = 1.0;

  template <typename T>
  bool operator()(T const* const* parameters, T* residuals) const {
    T q[4], diff[4];
    joint.Rotation(parameters, q);
    const T key_q[4] = {T(key_inverse.w()), T(key_inverse.x()), T(key_inverse.y()), T(key_inverse.z())};
    ceres::QuaternionProduct(key_q, q, diff);
    ceres::QuaternionToAngleAxis(diff, residuals);
    for (int i = 0; i < 3; ++i) residuals[i] *= T(inv_sigma_rad);
    return true;
  }
};

// Residual (FK position of the keyed joint - key) / sigma (3 entries, metres over metres).
// The chain starts at an anchor whose world frame is known (the motion root's heading and
// position from the sketch, or a skeleton root's parentless frame) and runs to the keyed
// joint's parent; only those rotations move the keyed joint.
struct PositionKeyFunctor {
  Eigen::Quaterniond anchor_prefix = Eigen::Quaterniond::Identity();  // e.g. the heading yaw
  Eigen::Vector3d anchor_position_m = Eigen::Vector3d::Zero();
  std::vector<JointSource> chain;              // anchor first, keyed joint's parent last
  std::vector<Eigen::Vector3d> translations_m;  // chain.size() entries: offset of chain[i+1] (last: keyed joint) in chain[i]'s frame
  Eigen::Vector3d key_m = Eigen::Vector3d::Zero();
  double inv_sigma_m = 1.0;

  template <typename T>
  bool operator()(T const* const* parameters, T* residuals) const {
    T world[4] = {T(anchor_prefix.w()), T(anchor_prefix.x()), T(anchor_prefix.y()), T(anchor_prefix.z())};
    T position[3] = {T(anchor_position_m.x()), T(anchor_position_m.y()), T(anchor_position_m.z())};
    for (size_t i = 0; i < chain.size(); ++i) {
      T local[4], composed[4], step[3];
      chain[i].Rotation(parameters, local);
      ceres::QuaternionProduct(world, local, composed);
      for (int a = 0; a < 4; ++a) world[a] = composed[a];
      const T offset[3] = {T(translations_m[i].x()), T(translations_m[i].y()), T(translations_m[i].z())};
      ceres::UnitQuaternionRotatePoint(world, offset, step);
      for (int a = 0; a < 3; ++a) position[a] += step[a];
    }
    for (int a = 0; a < 3; ++a) residuals[a] = (position[a] - T(key_m[a])) * T(inv_sigma_m);
    return true;
  }
};

}  // namespace mocapfill::pca_internal
