#include "processing/pca/pca_edit.h"

#include <cmath>
#include <set>
#include <string>

#include "processing/pca/pca_basis.h"
#include "processing/pca/pca_layout.h"
#include "processing/pca/pca_projection.h"

namespace mocapfill {

namespace {

// The constant change of the model vector the dials ask for: sum beta_k sqrt(lambda_k) u_k.
Eigen::VectorXd DialOffset(const PcaModel& model, const std::vector<ComponentDial>& dials) {
  Eigen::VectorXd offset = Eigen::VectorXd::Zero(model.dim());
  for (const ComponentDial& dial : dials)
    offset += dial.sigmas * std::sqrt(model.variances[dial.component]) * model.components.col(dial.component);
  return offset;
}

}  // namespace

Status PcaEditOptions::Validate(const PcaModel& model) const {
  if (!(max_abs_sigmas > 0.0)) return InvalidArgument("max_abs_sigmas must be > 0");
  std::set<int> seen;
  for (const ComponentDial& dial : dials) {
    const std::string name = "dials: component " + std::to_string(dial.component + 1);
    if (dial.component < 0 || dial.component >= model.num_components())
      return InvalidArgument(name + " is out of range; the model has components 1.." +
                             std::to_string(model.num_components()));
    if (!seen.insert(dial.component).second) return InvalidArgument(name + " is given twice");
    if (!std::isfinite(dial.sigmas) || std::abs(dial.sigmas) > max_abs_sigmas)
      return InvalidArgument(name + " must move by at most " + std::to_string(max_abs_sigmas) + " sigmas, got " +
                             std::to_string(dial.sigmas));
  }
  return OkStatus();
}

Result<Eigen::MatrixXd> EditPoses(const PcaModel& model, const Eigen::MatrixXd& poses, const PcaEditOptions& options) {
  RETURN_IF_ERROR(ValidatePcaModel(model).WithContext("pca model"));
  RETURN_IF_ERROR(options.Validate(model));
  const int pose_dim = model.pose_dim();
  const int window = model.window_frames;
  if (poses.cols() != pose_dim)
    return InvalidArgument("poses have " + std::to_string(poses.cols()) + " channels, the model " +
                           std::to_string(pose_dim));
  if (poses.rows() < window)
    return InvalidArgument("a window model needs at least " + std::to_string(window) + " frames, got " +
                           std::to_string(poses.rows()));
  const Eigen::VectorXd offset = DialOffset(model, options.dials);
  if (window == 1) {
    if (options.keep_residual) return Eigen::MatrixXd(poses.rowwise() + offset.transpose());
    return Eigen::MatrixXd(ReconstructFromModel(model, ProjectOntoModel(model, poses)).rowwise() + offset.transpose());
  }
  // Window model: edit every sliding window, then average the overlapping frames.
  const int frames = static_cast<int>(poses.rows());
  const int lengths[] = {frames};
  Eigen::MatrixXd windows = StackWindows(poses, lengths, window, 1);
  if (!options.keep_residual) windows = ReconstructFromModel(model, ProjectOntoModel(model, windows));
  windows.rowwise() += offset.transpose();
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(frames, pose_dim);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(frames);
  for (Eigen::Index s = 0; s < windows.rows(); ++s)
    for (int w = 0; w < window; ++w) {
      sum.row(s + w) += windows.row(s).segment(w * pose_dim, pose_dim);
      count[s + w] += 1.0;
    }
  return Eigen::MatrixXd(sum.array().colwise() / count.array());
}

}  // namespace mocapfill
