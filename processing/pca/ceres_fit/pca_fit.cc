#include "processing/pca/ceres_fit/pca_fit.h"

#include <chrono>
#include <memory>
#include <vector>

#include "processing/core/rotation.h"
#include "processing/core/stopwatch.h"
#include "processing/pca/closed_form_fit.h"
#include "processing/pca/ceres_fit/internal/fit_common.h"
#include "processing/pca/ceres_fit/internal/linear_cost.h"
#include "processing/pca/pca_projection.h"

namespace mocapfill {

namespace {

using pca_internal::LinearCost;
using pca_internal::RowMajorMatrix;
using Clock = std::chrono::steady_clock;

// Residual (y_O(c) - target_O) / sigma_O on the masked channels of frame t, or nullptr.
LinearCost* MakeChannelCost(const PcaModel& model, const Eigen::MatrixXd& values, const ChannelMask& mask, int t,
                            const Eigen::VectorXd& sigma) {
  std::vector<int> rows;
  for (int c = 0; c < model.pose_dim(); ++c)
    if (mask(t, c)) rows.push_back(c);
  if (rows.empty()) return nullptr;
  RowMajorMatrix a(rows.size(), model.num_components());
  Eigen::VectorXd offset(rows.size());
  for (size_t i = 0; i < rows.size(); ++i) {
    a.row(i) = model.components.row(rows[i]) / sigma[rows[i]];
    offset[i] = (values(t, rows[i]) - model.mean[rows[i]]) / sigma[rows[i]];
  }
  return new LinearCost({a}, offset);
}

pca_internal::JointSource SubspaceSource(const PcaModel& model, int joint) {
  pca_internal::JointSource source;
  source.block = 0;
  source.basis = model.components.middleRows(3 * joint, 3);
  source.offset = model.mean.segment<3>(3 * joint);
  source.weight = model.channel_weights[3 * joint];
  source.mean = model.joint_means[joint];
  return source;
}

// Adds every residual block of the subspace objective over coefficients stored in
// `c` (frames x K, row-major, must outlive the problem).
void AddSubspaceResiduals(const PcaModel& model, const PcaKeyProblem& problem, const PcaFitOptions& options,
                          std::vector<double>& c, ceres::Problem& ceres_problem) {
  const int k = model.num_components();
  const int frames = problem.num_frames;
  const auto block = [&](int t) { return c.data() + static_cast<size_t>(t) * k; };
  const Eigen::VectorXd key_sigma = ChannelSigmas(model, options.key_sigma_deg, options.root_key_sigma);
  const Eigen::VectorXd guide_sigma = ChannelSigmas(model, options.guide_sigma_deg, options.guide_root_sigma);
  for (int t = 0; t < frames; ++t) ceres_problem.AddParameterBlock(block(t), k);
  for (int t = 0; t < frames; ++t) {
    if (problem.key_mask.size() != 0)
      if (LinearCost* cost = MakeChannelCost(model, problem.key_values, problem.key_mask, t, key_sigma))
        ceres_problem.AddResidualBlock(cost, nullptr, block(t));
    if (problem.guide_mask.size() != 0)
      if (LinearCost* cost = MakeChannelCost(model, problem.guide_values, problem.guide_mask, t, guide_sigma))
        ceres_problem.AddResidualBlock(cost, nullptr, block(t));
    if (options.prior_scale > 0.0) {
      RowMajorMatrix a = (options.prior_scale * model.variances.cwiseSqrt().cwiseInverse()).asDiagonal();
      ceres_problem.AddResidualBlock(new LinearCost({a}, Eigen::VectorXd::Zero(k)), nullptr, block(t));
    }
  }
  if (options.smoothness_scale > 0.0) {
    const RowMajorMatrix d = (options.smoothness_scale * model.coefficient_accel_rms.cwiseInverse()).asDiagonal();
    for (int t = 1; t + 1 < frames; ++t)
      ceres_problem.AddResidualBlock(new LinearCost({d, -2.0 * d, d}, Eigen::VectorXd::Zero(k)), nullptr,
                                     block(t - 1), block(t), block(t + 1));
  }
  for (const RotationKey& key : problem.rotation_keys) {
    auto* functor = new pca_internal::GeodesicKeyFunctor;
    functor->joint = SubspaceSource(model, key.joint);
    functor->key_inverse = key.rotation.normalized().conjugate();
    functor->inv_sigma_rad = 1.0 / (options.key_sigma_deg * kRadPerDeg);
    auto* cost = new ceres::DynamicAutoDiffCostFunction<pca_internal::GeodesicKeyFunctor,
                                                        pca_internal::kAutoDiffStride>(functor);
    cost->AddParameterBlock(k);
    cost->SetNumResiduals(3);
    ceres_problem.AddResidualBlock(cost, nullptr, block(key.frame));
  }
  for (const PositionKey& key : problem.position_keys) {
    auto* functor = new pca_internal::PositionKeyFunctor(pca_internal::MakePositionFunctor(
        model, problem, key, options.position_sigma_cm, [&](int joint) { return SubspaceSource(model, joint); }));
    auto* cost = new ceres::DynamicAutoDiffCostFunction<pca_internal::PositionKeyFunctor,
                                                        pca_internal::kAutoDiffStride>(functor);
    cost->AddParameterBlock(k);
    cost->SetNumResiduals(3);
    ceres_problem.AddResidualBlock(cost, pca_internal::MakePositionLoss(options), block(key.frame));
  }
}

// The starting coefficients: the caller's, else the closed-form fit of the channel keys.
Result<Eigen::MatrixXd> InitialCoefficients(const PcaModel& model, const PcaKeyProblem& problem,
                                            const PcaFitOptions& options) {
  if (problem.initial.size() != 0) return problem.initial;
  if (problem.key_mask.size() == 0) return Eigen::MatrixXd(Eigen::MatrixXd::Zero(problem.num_frames, model.num_components()));
  ClosedFormOptions closed;
  closed.noise_deg = options.key_sigma_deg;
  closed.root_noise = options.root_key_sigma;
  return ClosedFormCoefficients(model, problem.key_values, problem.key_mask, closed);
}

std::vector<double> ToRowMajor(const Eigen::MatrixXd& m) {
  std::vector<double> out(m.size());
  Eigen::Map<RowMajorMatrix>(out.data(), m.rows(), m.cols()) = m;
  return out;
}

}  // namespace

Result<PcaFitResult> FitPcaToKeys(const PcaModel& model, const PcaKeyProblem& problem, const PcaFitOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  RETURN_IF_ERROR(pca_internal::ValidateKeyProblem(model, problem, model.num_components()));
  ASSIGN_OR_RETURN(const ceres::Solver::Options solver_options, pca_internal::MakeSolverOptions(options));
  PcaFitResult result;
  Clock::time_point start = Clock::now();
  ASSIGN_OR_RETURN(const Eigen::MatrixXd initial, InitialCoefficients(model, problem, options));
  result.initial_guess_s = SecondsSince(start);

  start = Clock::now();
  std::vector<double> c = ToRowMajor(initial);
  ceres::Problem ceres_problem;
  AddSubspaceResiduals(model, problem, options, c, ceres_problem);
  result.build_s = SecondsSince(start);

  RETURN_IF_ERROR(pca_internal::SolveFit(solver_options, "PCA fit", ceres_problem, result.solve_s, result.report));
  result.coefficients = Eigen::Map<const RowMajorMatrix>(c.data(), problem.num_frames, model.num_components());
  if (!result.coefficients.allFinite()) return NumericalFailure("PCA fit produced non-finite coefficients");
  result.poses = ReconstructFromModel(model, result.coefficients);
  return result;
}

Result<double> SubspaceFitCost(const PcaModel& model, const PcaKeyProblem& problem, const PcaFitOptions& options,
                               const Eigen::MatrixXd& coefficients) {
  RETURN_IF_ERROR(options.Validate());
  RETURN_IF_ERROR(pca_internal::ValidateKeyProblem(model, problem, model.num_components()));
  if (coefficients.rows() != problem.num_frames || coefficients.cols() != model.num_components())
    return InvalidArgument("coefficients must be frames x K");
  std::vector<double> c = ToRowMajor(coefficients);
  ceres::Problem ceres_problem;
  AddSubspaceResiduals(model, problem, options, c, ceres_problem);
  double cost = 0.0;
  if (!ceres_problem.Evaluate(ceres::Problem::EvaluateOptions(), &cost, nullptr, nullptr, nullptr))
    return NumericalFailure("could not evaluate the PCA fit objective");
  return cost;
}

}  // namespace mocapfill
