#include "processing/core/rotation.h"

#include <cctype>
#include <cmath>
#include <limits>

namespace mocapfill {

std::optional<EulerOrder> EulerOrder::Parse(std::string_view text) {
  if (text.size() != 3) return std::nullopt;
  EulerOrder order;
  for (int i = 0; i < 3; ++i) {
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(text[i])));
    if (c < 'X' || c > 'Z') return std::nullopt;
    order.axes[i] = c - 'X';
  }
  if (order.axes[0] == order.axes[1] || order.axes[1] == order.axes[2] || order.axes[0] == order.axes[2])
    return std::nullopt;
  return order;
}

std::string EulerOrder::ToString() const {
  std::string s;
  for (int a : axes) s.push_back(static_cast<char>('X' + a));
  return s;
}

namespace {

Eigen::Vector3d Axis(int a) { return Eigen::Vector3d::Unit(a); }

// Wraps an angle (degrees) to the representative closest to `near`.
double WrapNear(double angle, double near) {
  return angle + 360.0 * std::round((near - angle) / 360.0);
}

}  // namespace

Eigen::Quaterniond EulerDegreesToQuaternion(const std::array<double, 3>& angles_deg, const EulerOrder& order) {
  Eigen::Quaterniond q = Eigen::Quaterniond::Identity();
  for (int i = 0; i < 3; ++i)
    q = q * Eigen::Quaterniond(Eigen::AngleAxisd(angles_deg[i] * kRadPerDeg, Axis(order.axes[i])));
  return q.normalized();
}

std::array<double, 3> QuaternionToEulerDegrees(const Eigen::Quaterniond& q, const EulerOrder& order,
                                               const std::array<double, 3>* previous_deg) {
  // Tait-Bryan decomposition R = R_i(a) R_j(b) R_k(c) for distinct axes i, j, k.
  // With parity sign s = +1 for cyclic (i, j, k) and -1 otherwise:
  //   b = asin(s * R(i, k)), a = atan2(-s * R(j, k), R(k, k)), c = atan2(-s * R(i, j), R(i, i)).
  const Eigen::Matrix3d r = q.normalized().toRotationMatrix();
  const int i = order.axes[0], j = order.axes[1], k = order.axes[2];
  const double s = ((j - i + 3) % 3 == 1) ? 1.0 : -1.0;
  const double sb = std::clamp(s * r(i, k), -1.0, 1.0);
  double a, b, c;
  b = std::asin(sb);
  if (std::abs(sb) < 1.0 - 1e-12) {
    a = std::atan2(-s * r(j, k), r(k, k));
    c = std::atan2(-s * r(i, j), r(i, i));
  } else {
    // Gimbal lock: only a +- c is defined; keep c from the previous frame when known.
    c = previous_deg ? (*previous_deg)[2] * kRadPerDeg : 0.0;
    const Eigen::Matrix3d rc = Eigen::AngleAxisd(c, Axis(k)).toRotationMatrix();
    const Eigen::Matrix3d rb = Eigen::AngleAxisd(b, Axis(j)).toRotationMatrix();
    const Eigen::Matrix3d ra = r * rc.transpose() * rb.transpose();
    // ra is a rotation about axis i: read its angle from the two other axes.
    const int u = (i + 1) % 3, w = (i + 2) % 3;
    a = std::atan2(ra(w, u), ra(u, u));
  }
  std::array<double, 3> first{a * kDegPerRad, b * kDegPerRad, c * kDegPerRad};
  if (!previous_deg) return first;
  // The second solution: (a + 180, 180 - b, c + 180).
  std::array<double, 3> second{first[0] + 180.0, 180.0 - first[1], first[2] + 180.0};
  double best_cost = std::numeric_limits<double>::infinity();
  std::array<double, 3> best = first;
  for (auto candidate : {first, second}) {
    double cost = 0.0;
    for (int n = 0; n < 3; ++n) {
      candidate[n] = WrapNear(candidate[n], (*previous_deg)[n]);
      cost += std::abs(candidate[n] - (*previous_deg)[n]);
    }
    if (cost < best_cost) {
      best_cost = cost;
      best = candidate;
    }
  }
  return best;
}

void MakeHemisphereContinuous(std::vector<Eigen::Quaterniond>& quats, size_t first, size_t count, size_t stride) {
  for (size_t n = 1; n < count; ++n) {
    const Eigen::Quaterniond& prev = quats[first + (n - 1) * stride];
    Eigen::Quaterniond& cur = quats[first + n * stride];
    if (prev.coeffs().dot(cur.coeffs()) < 0.0) cur.coeffs() = -cur.coeffs();
  }
}

double GeodesicAngle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) {
  // 2 * atan2(|v|, |w|) of the relative rotation is accurate for tiny angles, unlike acos.
  const Eigen::Quaterniond d = a.conjugate() * b;
  return 2.0 * std::atan2(d.vec().norm(), std::abs(d.w()));
}

Eigen::Quaterniond ExpMap(const Eigen::Vector3d& v) {
  const double angle = v.norm();
  if (angle < 1e-12) return Eigen::Quaterniond(1.0, 0.5 * v.x(), 0.5 * v.y(), 0.5 * v.z()).normalized();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, v / angle));
}

Eigen::Vector3d LogMap(const Eigen::Quaterniond& q_in) {
  Eigen::Quaterniond q = q_in.normalized();
  if (q.w() < 0.0) q.coeffs() = -q.coeffs();
  const double s = q.vec().norm();
  if (s < 1e-12) return 2.0 * q.vec();
  const double angle = 2.0 * std::atan2(s, q.w());
  return q.vec() * (angle / s);
}

double WrapToPi(double angle) {
  angle = std::remainder(angle, 2.0 * kPi);
  return angle <= -kPi ? angle + 2.0 * kPi : angle;
}

Eigen::Quaterniond NormalisedOrSeed(const Eigen::Vector4d& sum, const Eigen::Quaterniond& seed) {
  if (sum.norm() < 1e-12) return seed;
  Eigen::Quaterniond q;
  q.coeffs() = sum.normalized();
  return q;
}

void AccumulateSignAligned(const Eigen::Quaterniond& q, const Eigen::Quaterniond& seed, Eigen::Vector4d& sum) {
  if (q.coeffs().dot(seed.coeffs()) < 0.0) {
    sum -= q.coeffs();
  } else {
    sum += q.coeffs();
  }
}

Eigen::Quaterniond MeanRotation(std::span<const Eigen::Quaterniond> rotations) {
  if (rotations.empty()) return Eigen::Quaterniond::Identity();
  Eigen::Quaterniond seed = rotations.front();
  for (int pass = 0; pass < 2; ++pass) {
    Eigen::Vector4d sum = Eigen::Vector4d::Zero();
    for (const Eigen::Quaterniond& q : rotations) AccumulateSignAligned(q, seed, sum);
    seed = NormalisedOrSeed(sum, seed);
  }
  return seed.normalized();
}

void SplitHeading(const Eigen::Quaterniond& world, double& heading_rad, Eigen::Quaterniond& tilt) {
  const double w = world.w(), y = world.y();
  if (w * w + y * y < 1e-24) {
    heading_rad = 0.0;
    tilt = world;
    return;
  }
  heading_rad = WrapToPi(2.0 * std::atan2(y, w));
  tilt = (YawRotation(-heading_rad) * world).normalized();
}

Eigen::Quaterniond YawRotation(double angle_rad) {
  return Eigen::Quaterniond(std::cos(0.5 * angle_rad), 0.0, std::sin(0.5 * angle_rad), 0.0);
}

}  // namespace mocapfill
