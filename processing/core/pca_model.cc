#include "processing/core/pca_model.h"

#include <cmath>
#include <string>

namespace mocapfill {

namespace {

// Components must be orthonormal to this accuracy; a model that fails it is corrupt.
constexpr double kOrthonormalTolerance = 1e-6;

std::string Field(const char* name, long got, long expected) {
  return std::string(name) + " has " + std::to_string(got) + " entries, expected " + std::to_string(expected);
}

}  // namespace

Status PcaModel::Validate() const {
  const PcaModel& m = *this;
  const long joints = m.num_joints();
  if (joints == 0) return InvalidData("model has no joints");
  if (static_cast<long>(m.joint_means.size()) != joints)
    return InvalidData(Field("joint_means", m.joint_means.size(), joints));
  for (const Eigen::Quaterniond& q : m.joint_means)
    if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > 1e-6) return InvalidData("joint_means holds a non-unit rotation");
  if (m.root_joint < -1 || m.root_joint >= joints) return InvalidData("root_joint is out of range");
  if (m.num_root_features < 0 || m.num_root_features > 64) return InvalidData("num_root_features is out of range");
  if (!(m.sample_rate_hz > 0.0 && std::isfinite(m.sample_rate_hz))) return InvalidData("sample_rate_hz must be > 0");
  if (m.window_frames < 1 || m.window_frames > 100000) return InvalidData("window_frames is out of range");
  const long pose = m.pose_dim(), dim = m.dim(), k = m.num_components();
  if (m.channel_weights.size() != pose) return InvalidData(Field("channel_weights", m.channel_weights.size(), pose));
  if (!(m.channel_weights.array() > 0.0).all() || !m.channel_weights.allFinite())
    return InvalidData("channel_weights must be finite and > 0");
  if (m.mean.size() != dim) return InvalidData(Field("mean", m.mean.size(), dim));
  if (m.components.rows() != dim) return InvalidData(Field("components rows", m.components.rows(), dim));
  if (k < 1 || k > dim) return InvalidData("model must have between 1 and " + std::to_string(dim) + " components");
  if (m.variances.size() != k) return InvalidData(Field("variances", m.variances.size(), k));
  if (m.spectrum.size() != dim) return InvalidData(Field("spectrum", m.spectrum.size(), dim));
  if (m.residual_variance.size() != dim) return InvalidData(Field("residual_variance", m.residual_variance.size(), dim));
  if (!m.residual_variance.allFinite() || !(m.residual_variance.array() >= 0.0).all())
    return InvalidData("residual_variance must be finite and >= 0");
  if (m.coefficient_accel_rms.size() != k) return InvalidData(Field("coefficient_accel_rms", m.coefficient_accel_rms.size(), k));
  if (m.channel_accel_rms.size() != pose) return InvalidData(Field("channel_accel_rms", m.channel_accel_rms.size(), pose));
  if (!m.mean.allFinite() || !m.components.allFinite() || !m.spectrum.allFinite())
    return InvalidData("model holds non-finite numbers");
  if (!(m.variances.array() > 0.0).all() || !m.variances.allFinite()) return InvalidData("variances must be finite and > 0");
  if (!(m.spectrum.array() >= 0.0).all()) return InvalidData("spectrum must be >= 0");
  if (!(m.coefficient_accel_rms.array() > 0.0).all() || !(m.channel_accel_rms.array() > 0.0).all() ||
      !m.coefficient_accel_rms.allFinite() || !m.channel_accel_rms.allFinite())
    return InvalidData("smoothness sigmas must be finite and > 0");
  const Eigen::MatrixXd gram = m.components.transpose() * m.components;
  if ((gram - Eigen::MatrixXd::Identity(k, k)).cwiseAbs().maxCoeff() > kOrthonormalTolerance)
    return InvalidData("components are not orthonormal");
  return OkStatus();
}

}  // namespace mocapfill
