// Closed-form regularised fit of a pose PCA model to partially observed poses
// (after Blanz, Mehl, Vetter and Seidel 2004). Per frame, with the
// observed channels O: minimise |P_O(mu + U c) - y_O|^2_sigma + c^T Lambda^-1 c, i.e. the
// conditional mean of the Gaussian model given noisy observations. It is the `pca`
// baseline fill method and the initial guess of the Ceres fit (pca_fit.h).
#pragma once

#include <Eigen/Core>

#include "processing/core/pca_model.h"
#include "processing/core/status.h"
#include "processing/pca/pca_layout.h"

namespace mocapfill {

struct ClosedFormOptions {
  // Observation noise sigma_n of tangent channels in degrees, scaled by the channel weight
  // like the channels themselves. Must be > 0 and finite.
  double noise_deg = 1.0;
  // Observation noise of weighted root-feature channels (centimetre-like units, > 0).
  double root_noise = 1.0;
  // Adds the model's per-channel residual variance (what the K components cannot express,
  // PcaModel::residual_variance) to every observed channel's noise variance.
  // Without it the conditional mean trusts observations the subspace cannot reproduce and
  // extrapolates, and the unkeyed joints come out worse than the mean pose (docs/pca.md).
  bool include_model_residual = true;

  Status Validate() const;
};

// Coefficients (frames x K) such that mu + U c_t is the conditional mean of frame t given
// its observed channels. `values` (frames x pose_dim, weighted units) is read only where
// `observed` is true. A frame without observations gets c_t = 0 (the mean pose).
// Frames sharing an observation pattern share one factorisation, so a sketch with the same
// keyed joints on every frame costs one K x K Cholesky in total.
// Errors: invalid options or model, a window model, size mismatches, non-finite observed
// values (kInvalidArgument).
Result<Eigen::MatrixXd> ClosedFormCoefficients(const PcaModel& model, const Eigen::MatrixXd& values,
                                               const ChannelMask& observed, const ClosedFormOptions& options);

// The `pca` baseline: observed entries of `values` are kept, every other entry is filled
// from the closed-form reconstruction mu + U c_t. Same errors as ClosedFormCoefficients.
Result<Eigen::MatrixXd> ClosedFormFill(const PcaModel& model, const Eigen::MatrixXd& values,
                                       const ChannelMask& observed, const ClosedFormOptions& options);

}  // namespace mocapfill
