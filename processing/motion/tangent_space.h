// Signal space of every analysis and synthesis stage, free of Euler wrap-around and gimbal
// lock while a joint stays within about 150 degrees of its reference.
//
// Joint rotations become "tangent coordinates" v = Log(Rbar^-1 R) about a per-joint
// reference rotation Rbar (the mean over a clip or a database), free of Euler wrap-around.
// The motion root (the joint that carries world motion, e.g. Bandai-Namco "Hips") is split
// into a heading yaw about the up axis (+Y) and the remaining tilt: its tangent columns hold
// the tilt about the mean tilt, and its world motion becomes heading-invariant root
// features (height, planar velocity in the heading frame, yaw rate). Heading and planar
// position are re-integrated from the features, so Decompose -> Compose is exact up to
// floating-point rounding and a clip can be edited in signal space without wrapping.
// The layout of the columns and the reference type are plain data in
// processing/core/signal_layout.h.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/rotation.h"
#include "processing/core/signal_layout.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"

namespace mocapfill {

// The joint that carries the character's world motion. The pelvis, i.e. the first joint (index
// order) with two or more children, when every joint whose translation is animated in any of
// `clips` is the pelvis or one of its ancestors (Bandai-Namco: "Hips", even in the clips where
// the static-looking "joint_Root" above it translates too); otherwise the first translating
// joint; for a chain without branches where nothing translates, the first root.
int FindMotionRoot(const Skeleton& skeleton, std::span<const MotionClip* const> clips);

// Reference rotations of the clips (each joint's MeanRotation over every frame of every
// clip; the root's entry from its world tilts). All clips must be valid for `skeleton`.
// root_joint = -1 disables the heading split.
TangentReference ComputeTangentReference(const Skeleton& skeleton, std::span<const MotionClip* const> clips,
                                         int root_joint);

// World motion of the motion root, one entry per frame.
struct RootTrajectory {
  std::vector<double> heading_rad;          // yaw about +Y, unwrapped (consecutive |diff| < pi)
  std::vector<Eigen::Vector3d> position_m;  // world position of the root joint
  std::vector<Eigen::Quaterniond> tilt;     // world rotation with the heading removed
};

// World trajectory of `root_joint` (its local transform composed with its ancestors').
RootTrajectory ExtractRootTrajectory(const Skeleton& skeleton, const MotionClip& clip, int root_joint);

// Root features of a trajectory sampled at rate_hz. A one-frame trajectory has zero velocities.
Eigen::MatrixXd RootFeaturesFromTrajectory(const RootTrajectory& trajectory, double rate_hz);

// Inverse of RootFeaturesFromTrajectory for heading and position: starts at
// (start_heading_rad, start_position_m) and integrates rows 0..T-2; height is taken from
// the feature column directly. The tilt member is left empty.
RootTrajectory IntegrateRootFeatures(const Eigen::MatrixXd& features, double rate_hz, double start_heading_rad,
                                     const Eigen::Vector3d& start_position_m);

// A clip expressed in signal space.
struct ClipSignals {
  Eigen::MatrixXd tangent;        // T x 3J; the root joint's columns hold Log(mean_tilt^-1 * tilt)
  Eigen::MatrixXd root_features;  // T x kNumRootFeatures; 0 columns when reference.root_joint < 0
  double start_heading_rad = 0.0;                            // heading at frame 0
  Eigen::Vector3d start_position_m = Eigen::Vector3d::Zero();  // root world position at frame 0
};

// Clip -> signal space about `reference` (which must have one mean per joint).
ClipSignals DecomposeClip(const Skeleton& skeleton, const MotionClip& clip, const TangentReference& reference);

// Signal space -> clip: R_j = Rbar_j * Exp(v_j); the root's world rotation is
// Ry(heading) * mean_tilt * Exp(v_root) with heading and position integrated from the root
// features, then converted back to a local transform through the root's ancestors as
// animated in `like`. Everything the signals do not describe (name, rate, translations of
// other joints, keys) is copied from `like`, which must have as many frames as the signals.
// Errors: size mismatches (kInvalidArgument), non-finite signals (kNumericalFailure).
Result<MotionClip> ComposeClip(const Skeleton& skeleton, const ClipSignals& signals,
                               const TangentReference& reference, const MotionClip& like);

}  // namespace mocapfill
