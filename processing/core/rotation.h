// Rotation helpers shared by every stage: Euler angles in any axis order (the BVH
// boundary), hemisphere continuity of quaternion tracks, geodesic angles, and the
// exponential/logarithm maps used for tangent coordinates.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace mocapfill {

// Order of three rotation axes as listed in a BVH CHANNELS line, e.g. "ZXY" = {2, 0, 1}.
// The rotation is intrinsic in the listed order: R = R_axis0(a0) * R_axis1(a1) * R_axis2(a2).
struct EulerOrder {
  std::array<int, 3> axes{2, 0, 1};

  // Parses "XYZ", "ZXY", ... (case-insensitive). All three axes must be distinct.
  static std::optional<EulerOrder> Parse(std::string_view text);
  std::string ToString() const;
  bool operator==(const EulerOrder&) const = default;
};

// Angles in degrees, in the order's own listing order (angles[i] about axes[i]).
Eigen::Quaterniond EulerDegreesToQuaternion(const std::array<double, 3>& angles_deg, const EulerOrder& order);

// Inverse of EulerDegreesToQuaternion. When previous_deg is given, the solution
// (among the two Euler solutions and their 360-degree shifts) closest to it is chosen,
// so angle curves stay continuous over time instead of jumping by 360 degrees.
std::array<double, 3> QuaternionToEulerDegrees(const Eigen::Quaterniond& q, const EulerOrder& order,
                                               const std::array<double, 3>* previous_deg = nullptr);

// Flips quaternions in place so that consecutive entries (stride apart) have a
// non-negative dot product: q and -q are the same rotation, and interpolation and
// filtering need the short arc.
void MakeHemisphereContinuous(std::vector<Eigen::Quaterniond>& quats, size_t first, size_t count, size_t stride);

// Geodesic angle between two rotations, in radians, in [0, pi]. Sign-invariant.
double GeodesicAngle(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b);

// Exponential and logarithm maps between rotation vectors (axis * angle, radians)
// and unit quaternions. Log returns the vector of the short-arc representative.
Eigen::Quaterniond ExpMap(const Eigen::Vector3d& v);
Eigen::Vector3d LogMap(const Eigen::Quaterniond& q);

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegPerRad = 180.0 / kPi;
constexpr double kRadPerDeg = kPi / 180.0;

}  // namespace mocapfill
