#include "processing/pca/closed_form_fit.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "processing/pca/pca_projection.h"

namespace mocapfill {

namespace {

// Maps observed residuals to coefficients for one observation pattern:
// c = Lambda^1/2 (A^T A + I)^-1 A^T S^-1 (y_O - mu_O) with A = S^-1 U_O Lambda^1/2, S = diag(sigma_O).
struct PatternSolver {
  std::vector<int> channels;
  Eigen::MatrixXd gain;  // K x |O|
};

PatternSolver MakePatternSolver(const PcaModel& model, const std::vector<int>& channels, const Eigen::VectorXd& sigma) {
  const int k = model.num_components();
  const Eigen::VectorXd sqrt_lambda = model.variances.cwiseSqrt();
  Eigen::MatrixXd a(channels.size(), k);
  Eigen::VectorXd inv_sigma(channels.size());
  for (size_t i = 0; i < channels.size(); ++i) {
    inv_sigma[i] = 1.0 / sigma[channels[i]];
    a.row(i) = inv_sigma[i] * model.components.row(channels[i]).cwiseProduct(sqrt_lambda.transpose());
  }
  Eigen::MatrixXd normal = a.transpose() * a;
  normal.diagonal().array() += 1.0;
  PatternSolver solver{channels, {}};
  solver.gain = sqrt_lambda.asDiagonal() * normal.llt().solve(a.transpose() * inv_sigma.asDiagonal());
  return solver;
}

Status CheckInputs(const PcaModel& model, const Eigen::MatrixXd& values, const ChannelMask& observed,
                   const ClosedFormOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  RETURN_IF_ERROR(ValidatePcaModel(model).WithContext("pca model"));
  if (model.window_frames != 1)
    return InvalidArgument("closed-form fitting needs a pose model; this model has windows of " +
                           std::to_string(model.window_frames) + " frames");
  if (values.cols() != model.pose_dim() || observed.cols() != values.cols() || observed.rows() != values.rows())
    return InvalidArgument("values (" + std::to_string(values.rows()) + " x " + std::to_string(values.cols()) +
                           ") and mask (" + std::to_string(observed.rows()) + " x " + std::to_string(observed.cols()) +
                           ") must both be frames x " + std::to_string(model.pose_dim()));
  for (Eigen::Index t = 0; t < values.rows(); ++t)
    for (Eigen::Index c = 0; c < values.cols(); ++c)
      if (observed(t, c) && !std::isfinite(values(t, c)))
        return InvalidArgument("observed value of channel " + ChannelName(model, static_cast<int>(c)) + " at frame " +
                               std::to_string(t) + " is not finite");
  return OkStatus();
}

}  // namespace

Status ClosedFormOptions::Validate() const {
  if (!(noise_deg > 0.0 && std::isfinite(noise_deg))) return InvalidArgument("noise_deg must be finite and > 0");
  if (!(root_noise > 0.0 && std::isfinite(root_noise))) return InvalidArgument("root_noise must be finite and > 0");
  return OkStatus();
}

Result<Eigen::MatrixXd> ClosedFormCoefficients(const PcaModel& model, const Eigen::MatrixXd& values,
                                               const ChannelMask& observed, const ClosedFormOptions& options) {
  RETURN_IF_ERROR(CheckInputs(model, values, observed, options));
  Eigen::VectorXd sigma = ChannelSigmas(model, options.noise_deg, options.root_noise);
  if (options.include_model_residual)
    sigma = (sigma.array().square() + model.residual_variance.array()).sqrt().matrix();
  Eigen::MatrixXd coefficients = Eigen::MatrixXd::Zero(values.rows(), model.num_components());
  std::map<std::vector<int>, PatternSolver> solvers;
  std::vector<int> channels;
  for (Eigen::Index t = 0; t < values.rows(); ++t) {
    channels.clear();
    for (int c = 0; c < model.pose_dim(); ++c)
      if (observed(t, c)) channels.push_back(c);
    if (channels.empty()) continue;
    auto it = solvers.find(channels);
    if (it == solvers.end()) it = solvers.emplace(channels, MakePatternSolver(model, channels, sigma)).first;
    Eigen::VectorXd residual(channels.size());
    for (size_t i = 0; i < channels.size(); ++i) residual[i] = values(t, channels[i]) - model.mean[channels[i]];
    coefficients.row(t) = (it->second.gain * residual).transpose();
  }
  return coefficients;
}

Result<Eigen::MatrixXd> ClosedFormFill(const PcaModel& model, const Eigen::MatrixXd& values,
                                       const ChannelMask& observed, const ClosedFormOptions& options) {
  ASSIGN_OR_RETURN(const Eigen::MatrixXd coefficients, ClosedFormCoefficients(model, values, observed, options));
  const Eigen::MatrixXd rebuilt = ReconstructFromModel(model, coefficients);
  return Eigen::MatrixXd(observed.select(values.array(), rebuilt.array()).matrix());
}

}  // namespace mocapfill
