#include "processing/pca/ceres_fit/internal/fit_common.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <thread>

#include "processing/core/rotation.h"
#include "processing/core/stopwatch.h"

namespace mocapfill {

Status PcaFitOptions::Validate() const {
  const auto positive = [](double v) { return v > 0.0 && std::isfinite(v); };
  const auto non_negative = [](double v) { return v >= 0.0 && std::isfinite(v); };
  if (!positive(key_sigma_deg)) return InvalidArgument("key_sigma_deg must be finite and > 0");
  if (!positive(root_key_sigma)) return InvalidArgument("root_key_sigma must be finite and > 0");
  if (!positive(position_sigma_cm)) return InvalidArgument("position_sigma_cm must be finite and > 0");
  if (!non_negative(position_huber_cm)) return InvalidArgument("position_huber_cm must be finite and >= 0");
  if (!positive(guide_sigma_deg)) return InvalidArgument("guide_sigma_deg must be finite and > 0");
  if (!positive(guide_root_sigma)) return InvalidArgument("guide_root_sigma must be finite and > 0");
  if (!non_negative(prior_scale)) return InvalidArgument("prior_scale must be finite and >= 0");
  if (!non_negative(smoothness_scale)) return InvalidArgument("smoothness_scale must be finite and >= 0");
  if (max_iterations < 1) return InvalidArgument("max_iterations must be >= 1");
  if (!positive(function_tolerance)) return InvalidArgument("function_tolerance must be finite and > 0");
  if (num_threads < 0) return InvalidArgument("num_threads must be >= 0");
  return OkStatus();
}

namespace pca_internal {

namespace {

Status CheckMatrix(const char* name, const Eigen::MatrixXd& values, const ChannelMask& mask, int frames, int cols) {
  if (values.size() == 0 && mask.size() == 0) return OkStatus();
  if (values.rows() != frames || values.cols() != cols || mask.rows() != frames || mask.cols() != cols)
    return InvalidArgument(std::string(name) + " values and mask must be " + std::to_string(frames) + " x " +
                           std::to_string(cols));
  for (Eigen::Index t = 0; t < frames; ++t)
    for (Eigen::Index c = 0; c < cols; ++c)
      if (mask(t, c) && !std::isfinite(values(t, c)))
        return InvalidArgument(std::string(name) + " value at frame " + std::to_string(t) + ", channel " +
                               std::to_string(c) + " is not finite");
  return OkStatus();
}

bool IsAtOrBelow(const std::vector<int>& parents, int joint, int ancestor) {
  for (int j = joint; j >= 0; j = parents[j])
    if (j == ancestor) return true;
  return false;
}

Status CheckPositionKeys(const PcaModel& model, const PcaKeyProblem& problem) {
  if (problem.position_keys.empty()) return OkStatus();
  const FitKinematics& kin = problem.kinematics;
  const size_t joints = model.num_joints(), frames = problem.num_frames;
  if (kin.parents.size() != joints || kin.translations_m.size() != joints * frames)
    return InvalidArgument("kinematics must give parents for " + std::to_string(joints) + " joints and " +
                           std::to_string(joints * frames) + " translations");
  for (size_t j = 0; j < joints; ++j)
    if (kin.parents[j] >= static_cast<int>(j) || kin.parents[j] < -1)
      return InvalidArgument("kinematics: parent of joint " + std::to_string(j) + " is not an earlier joint");
  if (model.root_joint >= 0 && (kin.root_heading_rad.size() != frames || kin.root_position_m.size() != frames))
    return InvalidArgument("kinematics must give the root heading and position at every frame");
  for (size_t i = 0; i < problem.position_keys.size(); ++i) {
    const PositionKey& key = problem.position_keys[i];
    const std::string name = "position key " + std::to_string(i);
    if (key.frame < 0 || key.frame >= problem.num_frames) return InvalidArgument(name + ": frame out of range");
    if (key.joint < 0 || key.joint >= model.num_joints()) return InvalidArgument(name + ": joint out of range");
    if (!key.position_m.allFinite()) return InvalidArgument(name + ": position is not finite");
    if (model.root_joint >= 0 && !IsAtOrBelow(kin.parents, key.joint, model.root_joint))
      return InvalidArgument(name + ": joint " + model.joint_names[key.joint] + " is not below the root joint " +
                             model.joint_names[model.root_joint]);
    if (key.joint == model.root_joint || kin.parents[key.joint] < 0)
      return InvalidArgument(name + ": joint " + model.joint_names[key.joint] +
                             " carries the root motion, which comes from the sketch and cannot be fitted");
  }
  return OkStatus();
}

}  // namespace

Status ValidateKeyProblem(const PcaModel& model, const PcaKeyProblem& problem, int initial_cols) {
  RETURN_IF_ERROR(ValidatePcaModel(model).WithContext("pca model"));
  if (model.window_frames != 1)
    return InvalidArgument("fitting keys needs a pose model; this model has windows of " +
                           std::to_string(model.window_frames) + " frames");
  if (problem.num_frames < 1) return InvalidArgument("num_frames must be >= 1");
  RETURN_IF_ERROR(CheckMatrix("key", problem.key_values, problem.key_mask, problem.num_frames, model.pose_dim()));
  RETURN_IF_ERROR(CheckMatrix("guide", problem.guide_values, problem.guide_mask, problem.num_frames, model.pose_dim()));
  for (size_t i = 0; i < problem.rotation_keys.size(); ++i) {
    const RotationKey& key = problem.rotation_keys[i];
    const std::string name = "rotation key " + std::to_string(i);
    if (key.frame < 0 || key.frame >= problem.num_frames) return InvalidArgument(name + ": frame out of range");
    if (key.joint < 0 || key.joint >= model.num_joints()) return InvalidArgument(name + ": joint out of range");
    if (!key.rotation.coeffs().allFinite() || std::abs(key.rotation.norm() - 1.0) > 1e-6)
      return InvalidArgument(name + ": rotation is not a unit quaternion");
  }
  RETURN_IF_ERROR(CheckPositionKeys(model, problem));
  if (problem.initial.size() != 0 &&
      (problem.initial.rows() != problem.num_frames || problem.initial.cols() != initial_cols || !problem.initial.allFinite()))
    return InvalidArgument("initial must be " + std::to_string(problem.num_frames) + " x " +
                           std::to_string(initial_cols) + " finite values");
  return OkStatus();
}

Result<ceres::Solver::Options> MakeSolverOptions(const PcaFitOptions& options) {
  ceres::Solver::Options o;
  o.minimizer_type = ceres::TRUST_REGION;
  o.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  // The default problem is linear least squares: a large initial radius makes the first
  // LM step a Gauss-Newton step, which is exact, so the fit converges in about 2 steps.
  o.initial_trust_region_radius = 1e16;
  o.max_trust_region_radius = 1e16;
  o.max_num_iterations = options.max_iterations;
  o.function_tolerance = options.function_tolerance;
  o.num_threads = options.num_threads > 0 ? options.num_threads
                                          : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  o.logging_type = ceres::SILENT;
  o.minimizer_progress_to_stdout = false;
  const bool suite = ceres::IsSparseLinearAlgebraLibraryTypeAvailable(ceres::SUITE_SPARSE);
  const bool eigen = ceres::IsSparseLinearAlgebraLibraryTypeAvailable(ceres::EIGEN_SPARSE);
  if (options.linear_solver == FitLinearSolver::kDenseQr || (!suite && !eigen)) {
    if (options.linear_solver == FitLinearSolver::kSparseNormalCholesky)
      return Unsupported("this Ceres build has no sparse linear algebra library (SuiteSparse or Eigen sparse)");
    o.linear_solver_type = ceres::DENSE_QR;
  } else {
    o.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
    o.sparse_linear_algebra_library_type = suite ? ceres::SUITE_SPARSE : ceres::EIGEN_SPARSE;
  }
  std::string error;
  if (!o.IsValid(&error)) return Internal("ceres options: " + error);
  return o;
}

Status SolveFit(const ceres::Solver::Options& options, const std::string& fit, ceres::Problem& problem,
                double& solve_s, SolverReport& report) {
  const auto start = std::chrono::steady_clock::now();
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  solve_s = SecondsSince(start);
  report = MakeReport(summary, options);
  if (summary.termination_type == ceres::FAILURE || summary.termination_type == ceres::USER_FAILURE)
    return NumericalFailure(fit + " failed: " + summary.message);
  return OkStatus();
}

SolverReport MakeReport(const ceres::Solver::Summary& summary, const ceres::Solver::Options& options) {
  SolverReport report;
  report.termination_type = ceres::TerminationTypeToString(summary.termination_type);
  report.converged = summary.termination_type == ceres::CONVERGENCE || summary.termination_type == ceres::USER_SUCCESS;
  // Ceres records the evaluation at the start as iteration 0; count only the steps taken.
  report.iterations = std::max(0, static_cast<int>(summary.iterations.size()) - 1);
  report.initial_cost = summary.initial_cost;
  report.final_cost = summary.final_cost;
  report.solve_time_s = summary.total_time_in_seconds;
  report.preprocess_time_s = summary.preprocessor_time_in_seconds;
  report.jacobian_time_s = summary.jacobian_evaluation_time_in_seconds + summary.residual_evaluation_time_in_seconds;
  report.linear_solver_time_s = summary.linear_solver_time_in_seconds;
  report.message = summary.message;
  report.linear_solver = ceres::LinearSolverTypeToString(summary.linear_solver_type_used);
  if (summary.linear_solver_type_used == ceres::SPARSE_NORMAL_CHOLESKY)
    report.linear_solver += std::string(" (") +
                            ceres::SparseLinearAlgebraLibraryTypeToString(options.sparse_linear_algebra_library_type) + ")";
  report.num_parameters = summary.num_effective_parameters;
  report.num_residuals = summary.num_residuals;
  report.num_residual_blocks = summary.num_residual_blocks;
  return report;
}

std::vector<int> KinematicChain(const PcaModel& model, const FitKinematics& kinematics, int joint) {
  std::vector<int> chain;
  for (int j = kinematics.parents[joint]; j >= 0; j = kinematics.parents[j]) {
    chain.push_back(j);
    if (j == model.root_joint) break;
  }
  if (joint == model.root_joint) chain.clear();
  std::reverse(chain.begin(), chain.end());
  return chain;
}

PositionKeyFunctor MakePositionFunctor(const PcaModel& model, const PcaKeyProblem& problem, const PositionKey& key,
                                       double sigma_cm, const SourceFactory& make_source) {
  const FitKinematics& kin = problem.kinematics;
  const int joints = model.num_joints();
  const auto translation = [&](int j) { return kin.translations_m[static_cast<size_t>(key.frame) * joints + j]; };
  PositionKeyFunctor functor;
  functor.key_m = key.position_m;
  functor.inv_sigma_m = 100.0 / sigma_cm;
  const std::vector<int> chain = KinematicChain(model, kin, key.joint);
  const int anchor = chain.empty() ? key.joint : chain.front();
  if (model.root_joint >= 0) {
    functor.anchor_prefix = Eigen::Quaterniond(Eigen::AngleAxisd(kin.root_heading_rad[key.frame], Eigen::Vector3d::UnitY()));
    functor.anchor_position_m = kin.root_position_m[key.frame];
  } else {
    functor.anchor_position_m = translation(anchor);  // a skeleton root: local = world
  }
  for (size_t i = 0; i < chain.size(); ++i) {
    functor.chain.push_back(make_source(chain[i]));
    functor.translations_m.push_back(translation(i + 1 < chain.size() ? chain[i + 1] : key.joint));
  }
  return functor;
}

ceres::LossFunction* MakePositionLoss(const PcaFitOptions& options) {
  if (options.position_huber_cm <= 0.0) return nullptr;
  return new ceres::HuberLoss(options.position_huber_cm / options.position_sigma_cm);
}

}  // namespace pca_internal
}  // namespace mocapfill
