// Estimating the linear Gaussian part of a PcaModel from weighted pose vectors: mean,
// covariance eigen-decomposition, choice of the number of components by explained variance
// (the thesis's compression), and the per-frame smoothness statistics used by the Ceres fit
// (pca_fit.h). Works on plain Eigen matrices; clip handling is in pca_model_builder.h.
#pragma once

#include <Eigen/Core>
#include <span>

#include "processing/core/pca_model.h"
#include "processing/core/status.h"

namespace mocapfill {

struct PcaBasisOptions {
  // Keep the fewest components whose cumulative share of the total variance reaches this
  // fraction. Range (0, 1]; 1 keeps every component with non-zero variance.
  double variance_kept = 0.95;
  // Upper bound on the number of components (>= 1). The cap keeps the Ceres fit fast: its
  // cost grows with the cube of the number of components.
  int max_components = 30;
  // 1 = pose PCA (default); W > 1 = window PCA over W consecutive frames, which captures
  // timing too.
  int window_frames = 1;
  // Hop between the windows used to estimate a window model (>= 1, frames); larger hops
  // make estimation cheaper on big databases. Ignored for pose PCA.
  int window_stride_frames = 1;

  // Fails with kInvalidArgument naming the offending field.
  Status Validate() const;
};

// Estimates mean, components, variances, spectrum, coefficient_accel_rms and
// channel_accel_rms of `model` from `poses` (rows = frames, pose_dim columns, already
// weighted), which hold contiguous segments (clips) of the given lengths one after the
// other. Second differences and windows never straddle a segment boundary. Sets
// model.window_frames and model.num_samples; leaves the layout fields untouched.
// Errors: invalid options or sizes (kInvalidArgument); fewer than two vectors, non-finite
// values or no variance at all (kInvalidData).
Status EstimatePcaBasis(const Eigen::MatrixXd& poses, std::span<const int> segment_lengths,
                        const PcaBasisOptions& options, PcaModel& model);

// Stacks windows of `window` consecutive rows (oldest first) of every segment, starting
// at offsets 0, stride, 2*stride, ... while the window fits in the segment. Returns a
// (count x window*cols) matrix. A segment shorter than the window contributes nothing.
Eigen::MatrixXd StackWindows(const Eigen::MatrixXd& rows, std::span<const int> segment_lengths, int window,
                             int stride);

}  // namespace mocapfill
