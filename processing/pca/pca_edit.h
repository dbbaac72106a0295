// Editing a motion with component dials (thesis chapter 5: a model
// "used to edit and enhance an animation after it was created"). Each dial moves one
// component's coefficient by beta standard deviations (beta * sqrt(lambda_k)) on every
// frame; the part of the motion the model does not explain (the residual) is kept by
// default so capture detail survives the edit.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/core/pca_model.h"
#include "processing/core/status.h"

namespace mocapfill {

struct ComponentDial {
  int component = 0;   // 0-based component index (the CLI's "--component 1=..." is 1-based)
  double sigmas = 0.0; // beta: change in standard deviations of that component
};

struct PcaEditOptions {
  std::vector<ComponentDial> dials;  // at most one dial per component
  // Bound on |beta|. Larger moves leave the data the model was built from.
  double max_abs_sigmas = 3.0;
  // true: y' = y + sum beta_k sqrt(lambda_k) u_k (residual kept, all dials 0 = identity);
  // false: y' = mu + U (c + delta), i.e. the edited motion is rebuilt from the model only.
  bool keep_residual = true;

  // kInvalidArgument naming the field: component out of [0, K), repeated component,
  // non-finite beta or |beta| > max_abs_sigmas, max_abs_sigmas not > 0.
  Status Validate(const PcaModel& model) const;
};

// Applies the dials to `poses` (frames x model.pose_dim(), weighted pose vectors). For a
// window model every frame gets the average over all windows of W frames that contain it
// (windows are slid one frame at a time), so the output has as many frames as the input.
// Errors: invalid options or model, wrong column count, fewer frames than a window
// (kInvalidArgument).
Result<Eigen::MatrixXd> EditPoses(const PcaModel& model, const Eigen::MatrixXd& poses, const PcaEditOptions& options);

}  // namespace mocapfill
