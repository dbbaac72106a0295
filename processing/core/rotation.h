// Rotation helpers shared by every stage: Euler angles in any axis order (the BVH
// boundary), hemisphere continuity of quaternion tracks, geodesic angles, and the
// exponential/logarithm maps used for tangent coordinates.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <optional>
#include <span>
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

// Mean of unit quaternions (the reference rotation of tangent coordinates): sign-align
// every quaternion to a seed (the first one), average the components, normalise; repeat
// once with the result as seed.
// Returns identity for an empty input or when the average vanishes.
Eigen::Quaterniond MeanRotation(std::span<const Eigen::Quaterniond> rotations);

// Splits a world rotation into R = Ry(heading) * tilt, where tilt has no twist about +Y
// (its quaternion has a zero y component; swing-twist decomposition about the up axis).
// heading_rad is in (-pi, pi]; it is 0 in the degenerate case of a 180-degree swing.
void SplitHeading(const Eigen::Quaterniond& world, double& heading_rad, Eigen::Quaterniond& tilt);

// The angle in (-pi, pi] that equals `angle` modulo 2 pi.
double WrapToPi(double angle);

// Rotation about +Y by `angle_rad`.
Eigen::Quaterniond YawRotation(double angle_rad);

// Building blocks of MeanRotation, for callers that average many tracks in one pass: adds q
// (sign-aligned to seed) to a component sum; the normalised sum, or the seed when it vanishes.
void AccumulateSignAligned(const Eigen::Quaterniond& q, const Eigen::Quaterniond& seed, Eigen::Vector4d& sum);
Eigen::Quaterniond NormalisedOrSeed(const Eigen::Vector4d& sum, const Eigen::Quaterniond& seed);

}  // namespace mocapfill
