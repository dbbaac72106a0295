// Full-pose variant of the key fit (pca_fit.h): the unknowns are the pose vectors,
// keyed joint blocks are constant, so keys hold exactly; a probabilistic-PCA prior keeps
// the free joints plausible.
#include <Eigen/Cholesky>
#include <chrono>
#include <string>
#include <vector>

#include "processing/core/stopwatch.h"
#include "processing/pca/closed_form_fit.h"
#include "processing/pca/ceres_fit/internal/fit_common.h"
#include "processing/pca/ceres_fit/internal/linear_cost.h"
#include "processing/pca/ceres_fit/pca_fit.h"
#include "processing/pca/pca_projection.h"

namespace mocapfill {

namespace {

using pca_internal::LinearCost;
using pca_internal::RowMajorMatrix;
using Clock = std::chrono::steady_clock;

// Channel groups that form one parameter block each: three per joint, then the root features.
struct Group {
  int first = 0;
  int size = 0;
};

std::vector<Group> MakeGroups(const PcaModel& model) {
  std::vector<Group> groups;
  for (int j = 0; j < model.num_joints(); ++j) groups.push_back({3 * j, 3});
  if (model.num_root_features > 0) groups.push_back({3 * model.num_joints(), model.num_root_features});
  return groups;
}

// True when the group is keyed at frame t; kInvalidArgument when only part of it is.
Result<bool> GroupKeyed(const PcaModel& model, const PcaKeyProblem& problem, const Group& g, int t) {
  if (problem.key_mask.size() == 0) return false;
  const int count = static_cast<int>(problem.key_mask.row(t).segment(g.first, g.size).count());
  if (count != 0 && count != g.size)
    return InvalidArgument("full-pose fit: channel " + ChannelName(model, g.first) + " group is partly keyed at frame " +
                           std::to_string(t) + "; key all channels of a joint together");
  return count == g.size;
}

// Probabilistic PCA prior as one linear map: |M (y - mu)|^2 with
// M^T M = U Lambda^-1 U^T + (I - U U^T) / sigma_res^2.
RowMajorMatrix PpcaPriorMatrix(const PcaModel& model) {
  const int k = model.num_components(), d = model.pose_dim();
  double residual_variance = k < d ? model.spectrum.tail(d - k).mean() : 0.0;
  // A floor keeps the matrix positive definite when the discarded spectrum is (near) zero.
  residual_variance = std::max(residual_variance, 1e-6 * model.spectrum[0]);
  const Eigen::MatrixXd& u = model.components;
  Eigen::MatrixXd precision = u * (model.variances.cwiseInverse().array() - 1.0 / residual_variance).matrix().asDiagonal() *
                              u.transpose();
  precision.diagonal().array() += 1.0 / residual_variance;
  return Eigen::MatrixXd(precision.llt().matrixU());
}

// Columns of `m` for group g as one block matrix.
RowMajorMatrix Columns(const RowMajorMatrix& m, const Group& g) { return m.middleCols(g.first, g.size); }

struct FullPoseState {
  std::vector<Group> groups;
  std::vector<double> y;  // frames x pose_dim, row-major
  int frames = 0;
  int pose_dim = 0;
  double* Block(int t, const Group& g) { return y.data() + static_cast<size_t>(t) * pose_dim + g.first; }
};

void AddPriorAndGuide(const PcaModel& model, const PcaKeyProblem& problem, const PcaFitOptions& options,
                      FullPoseState& s, ceres::Problem& ceres_problem) {
  const Eigen::VectorXd guide_sigma = ChannelSigmas(model, options.guide_sigma_deg, options.guide_root_sigma);
  const RowMajorMatrix prior = options.prior_scale * PpcaPriorMatrix(model);
  const Eigen::VectorXd prior_offset = prior * model.mean;
  std::vector<RowMajorMatrix> prior_blocks;
  for (const Group& g : s.groups) prior_blocks.push_back(Columns(prior, g));
  for (int t = 0; t < s.frames; ++t) {
    std::vector<double*> blocks;
    for (const Group& g : s.groups) blocks.push_back(s.Block(t, g));
    if (options.prior_scale > 0.0) ceres_problem.AddResidualBlock(new LinearCost(prior_blocks, prior_offset), nullptr, blocks);
    if (problem.guide_mask.size() == 0) continue;
    for (const Group& g : s.groups) {
      std::vector<int> rows;
      for (int i = 0; i < g.size; ++i)
        if (problem.guide_mask(t, g.first + i)) rows.push_back(i);
      if (rows.empty()) continue;
      RowMajorMatrix a = RowMajorMatrix::Zero(rows.size(), g.size);
      Eigen::VectorXd offset(rows.size());
      for (size_t r = 0; r < rows.size(); ++r) {
        const int c = g.first + rows[r];
        a(r, rows[r]) = 1.0 / guide_sigma[c];
        offset[r] = problem.guide_values(t, c) / guide_sigma[c];
      }
      ceres_problem.AddResidualBlock(new LinearCost({a}, offset), nullptr, s.Block(t, g));
    }
  }
}

void AddSmoothness(const PcaModel& model, const PcaFitOptions& options, FullPoseState& s, ceres::Problem& ceres_problem) {
  if (options.smoothness_scale <= 0.0) return;
  for (const Group& g : s.groups) {
    const RowMajorMatrix d =
        (options.smoothness_scale * model.channel_accel_rms.segment(g.first, g.size).cwiseInverse()).asDiagonal();
    for (int t = 1; t + 1 < s.frames; ++t)
      ceres_problem.AddResidualBlock(new LinearCost({d, -2.0 * d, d}, Eigen::VectorXd::Zero(g.size)), nullptr,
                                     s.Block(t - 1, g), s.Block(t, g), s.Block(t + 1, g));
  }
}

void AddPositionKeys(const PcaModel& model, const PcaKeyProblem& problem, const PcaFitOptions& options,
                     FullPoseState& s, ceres::Problem& ceres_problem) {
  for (const PositionKey& key : problem.position_keys) {
    std::vector<double*> blocks;
    auto source = [&](int joint) {
      pca_internal::JointSource src;
      src.block = static_cast<int>(blocks.size());
      src.weight = model.channel_weights[3 * joint];
      src.mean = model.joint_means[joint];
      blocks.push_back(s.Block(key.frame, s.groups[joint]));
      return src;
    };
    auto* functor = new pca_internal::PositionKeyFunctor(
        pca_internal::MakePositionFunctor(model, problem, key, options.position_sigma_cm, source));
    auto* cost = new ceres::DynamicAutoDiffCostFunction<pca_internal::PositionKeyFunctor,
                                                        pca_internal::kAutoDiffStride>(functor);
    for (size_t b = 0; b < blocks.size(); ++b) cost->AddParameterBlock(3);
    cost->SetNumResiduals(3);
    ceres_problem.AddResidualBlock(cost, pca_internal::MakePositionLoss(options), blocks);
  }
}

Result<Eigen::MatrixXd> InitialPoses(const PcaModel& model, const PcaKeyProblem& problem, const PcaFitOptions& options) {
  if (problem.initial.size() != 0) return problem.initial;
  if (problem.key_mask.size() == 0) return Eigen::MatrixXd(model.mean.transpose().replicate(problem.num_frames, 1));
  ClosedFormOptions closed;
  closed.noise_deg = options.key_sigma_deg;
  closed.root_noise = options.root_key_sigma;
  return ClosedFormFill(model, problem.key_values, problem.key_mask, closed);
}

}  // namespace

Result<PcaFitResult> FitFullPoseToKeys(const PcaModel& model, const PcaKeyProblem& problem,
                                       const PcaFitOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  RETURN_IF_ERROR(pca_internal::ValidateKeyProblem(model, problem, model.pose_dim()));
  if (!problem.rotation_keys.empty())
    return InvalidArgument("the full-pose fit takes keys as channel values (key_values), not rotation_keys");
  ASSIGN_OR_RETURN(const ceres::Solver::Options solver_options, pca_internal::MakeSolverOptions(options));
  PcaFitResult result;
  Clock::time_point start = Clock::now();
  ASSIGN_OR_RETURN(Eigen::MatrixXd initial, InitialPoses(model, problem, options));
  if (problem.key_mask.size() != 0) initial = problem.key_mask.select(problem.key_values.array(), initial.array()).matrix();
  result.initial_guess_s = SecondsSince(start);

  start = Clock::now();
  FullPoseState s;
  s.groups = MakeGroups(model);
  s.frames = problem.num_frames;
  s.pose_dim = model.pose_dim();
  s.y.resize(initial.size());
  Eigen::Map<RowMajorMatrix>(s.y.data(), initial.rows(), initial.cols()) = initial;
  ceres::Problem ceres_problem;
  for (int t = 0; t < s.frames; ++t)
    for (const Group& g : s.groups) ceres_problem.AddParameterBlock(s.Block(t, g), g.size);
  AddPriorAndGuide(model, problem, options, s, ceres_problem);
  AddSmoothness(model, options, s, ceres_problem);
  AddPositionKeys(model, problem, options, s, ceres_problem);
  for (int t = 0; t < s.frames; ++t)
    for (const Group& g : s.groups) {
      ASSIGN_OR_RETURN(const bool keyed, GroupKeyed(model, problem, g, t));
      if (keyed) ceres_problem.SetParameterBlockConstant(s.Block(t, g));
    }
  result.build_s = SecondsSince(start);

  RETURN_IF_ERROR(
      pca_internal::SolveFit(solver_options, "full-pose PCA fit", ceres_problem, result.solve_s, result.report));
  result.poses = Eigen::Map<const RowMajorMatrix>(s.y.data(), s.frames, model.pose_dim());
  if (!result.poses.allFinite()) return NumericalFailure("full-pose PCA fit produced non-finite poses");
  result.coefficients = ProjectOntoModel(model, result.poses);
  return result;
}

}  // namespace mocapfill
