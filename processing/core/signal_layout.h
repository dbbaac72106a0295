// The layout of signal-space matrices (algorithms.md 1.2-1.3): what their columns and rows
// are and the reference rotations the tangent columns are measured from.
//
// It lives in core because the .mfdb file format (formats/mfdb) stores matrices in this
// layout with their reference, and formats may depend only on core. The transforms into and
// out of signal space are algorithms: processing/motion/tangent_space.h.
//
// Columns: 3j + a is tangent component a (0 x, 1 y, 2 z) of joint j, radians; after the 3J
// tangent columns come the kNumRootFeatures root features, when there is a motion root.
// Rows: frames; a matrix of several clips concatenates their frames, one FrameSegment each.
#pragma once

#include <Eigen/Geometry>
#include <vector>

namespace mocapfill {

// Column of joint j's tangent component `axis` (0 x, 1 y, 2 z) in a T x 3J tangent matrix.
inline int TangentColumn(int joint, int axis) { return 3 * joint + axis; }

// Reference rotations of a tangent space. joint_means[j] is the mean local rotation of
// joint j, except for root_joint, whose entry is the mean world tilt (heading removed).
struct TangentReference {
  std::vector<Eigen::Quaterniond> joint_means;
  int root_joint = -1;  // motion root; -1 = no root split (every joint is a plain local tangent)
};

// Columns of the heading-invariant root feature matrix (T x kNumRootFeatures).
// Velocities are forward differences: row t describes the step from frame t to t + 1,
// expressed in the heading frame of frame t (forward = heading frame +Z, lateral = +X);
// the last row repeats the previous one so every frame has a row.
enum RootFeature : int {
  kRootHeight = 0,        // world height (Y) of the root, m
  kRootForward = 1,       // planar velocity along the heading frame's +Z, m/s
  kRootLateral = 2,       // planar velocity along the heading frame's +X, m/s
  kRootYawRate = 3,       // heading change per second, rad/s
  kNumRootFeatures = 4,
};

// Stable channel name of a root feature: "root.height_m", "root.forward_mps",
// "root.lateral_mps", "root.yaw_rate_radps".
const char* RootFeatureName(int feature);

// A run of consecutive rows of one clip inside a concatenated matrix. Computations over
// neighbouring rows (lagged correlation) never cross from one segment into the next.
struct FrameSegment {
  int first_row = 0;
  int num_rows = 0;
};

}  // namespace mocapfill
