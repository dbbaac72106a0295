// Euler angles to quaternions for the BVH importer's inner loop (a quarter of a million
// rotations per CMU clip). Same rotation as EulerDegreesToQuaternion (intrinsic, listed
// order, R = R_a0 R_a1 R_a2), about twice as fast: the axis order is a template
// parameter, each factor is an elementary quaternion, and sin/cos are evaluated after an
// exact reduction in degrees.
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstddef>

#include "processing/core/rotation.h"

namespace mocapfill::bvh {

using EulerComposer = Eigen::Quaterniond (*)(const std::array<double, 3>& angles_deg);

// The composer for an axis order (any of the six Tait-Bryan orders).
EulerComposer ComposerFor(const EulerOrder& order);

// Convenience form: ComposerFor(order)(angles_deg).
Eigen::Quaterniond ComposeEulerDegrees(const std::array<double, 3>& angles_deg, const EulerOrder& order);

// The rotation of three Euler angles in an order, from the sines and cosines of the halves
// of the angles (listed order): what an EulerComposer does after its trigonometry.
using HalfAngleComposer = Eigen::Quaterniond (*)(const double* half_sine, const double* half_cosine);
HalfAngleComposer HalfAngleComposerFor(const EulerOrder& order);

// SinCosDegrees of n angles, bit for bit, vectorised (with AVX2 where the build and the CPU
// have it): all of a motion row's angles at once, much faster than one at a time.
void SinCosDegreesBatch(const double* deg, size_t n, double* sine, double* cosine);

// sin and cos of an angle in degrees, within 1e-16 of libm for |deg| < 1e9 (exact
// reduction by multiples of 90 degrees, Taylor polynomials on [-45, 45] degrees); larger
// angles fall back to libm.
void SinCosDegrees(double deg, double& sine, double& cosine);

}  // namespace mocapfill::bvh
