// Fitting a pose PCA model to keyframe constraints with Ceres (thesis chapter 5; the
// formulation of Safonova et al. 2004 and Chai and Hodgins 2005: keys, prior, smoothness).
//
// Subspace variant (FitPcaToKeys): unknowns are the coefficients c_t (K per frame) and the
// pose is y_t = mu + U c_t. Least-squares residual blocks, each divided by its sigma:
//   keyed channels      (y_t - y_key) on keyed (frame, channel)   s_key = 1 deg (x weight)
//   geodesic keys       Log(R_key^-1 R_j(c_t))                    s_key
//   position keys       FK_j(c_t) - p_key (world, metres)         s_pos = 0.25 cm
//   prior               c_(t,k) / sqrt(lambda_k)                  1
//   smoothness          c_(t+1) - 2 c_t + c_(t-1)                 s_acc,k (database RMS)
//   guide               (y_t - y_guide) on guided channels        s_guide = 10 deg (x weight)
// Without geodesic or position keys the problem is linear least squares.
//
// Full-pose variant (FitFullPoseToKeys): unknowns are the pose vectors themselves, one
// block per joint (3 channels) and one for the root features per frame; keyed blocks are
// held constant so keys hold exactly. Prior: probabilistic PCA,
// |Lambda^-1/2 U^T (y - mu)|^2 + |(I - U U^T)(y - mu)|^2 / sigma_res^2 with sigma_res^2 the
// mean discarded eigenvalue; smoothness on y with the per-channel database RMS.
//
// Both return the Ceres summary as plain data (SolverReport) for reports.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "processing/core/pca_model.h"
#include "processing/core/status.h"
#include "processing/pca/pca_layout.h"

namespace mocapfill {

// A keyed local rotation of a model joint, fitted through the geodesic residual. The
// rotation is what the clip holds for that joint (for the motion root with a heading split:
// its world tilt, i.e. world rotation with the heading removed).
struct RotationKey {
  int frame = 0;
  int joint = 0;  // model joint index
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
};

// A keyed world position of a model joint (an animator's foot or hand placement), metres.
struct PositionKey {
  int frame = 0;
  int joint = 0;  // model joint index; must be the model's root joint or below it
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
};

// What forward kinematics needs besides the pose vector, per frame (from the sketch).
struct FitKinematics {
  std::vector<int> parents;  // per model joint, -1 for a skeleton root
  // Local translation of every joint at every frame, already scaled by the parent's rest
  // scale, frame-major [t * J + j], metres.
  std::vector<Eigen::Vector3d> translations_m;
  // Used when the model has a root joint (heading split): heading yaw about +Y (rad) and
  // world position (m) of the root joint per frame.
  std::vector<double> root_heading_rad;
  std::vector<Eigen::Vector3d> root_position_m;
};

// The data of one fit; sizes are frames x model.pose_dim() unless empty.
struct PcaKeyProblem {
  int num_frames = 0;
  Eigen::MatrixXd key_values;  // weighted pose values, read where key_mask is true
  ChannelMask key_mask;        // empty = no channel keys
  std::vector<RotationKey> rotation_keys;
  std::vector<PositionKey> position_keys;
  FitKinematics kinematics;    // required when position_keys is not empty
  Eigen::MatrixXd guide_values;  // optional guide (e.g. the fragment result); empty = none
  ChannelMask guide_mask;        // where the guide applies (usually the unkeyed joints)
  // Optional starting point (frames x K for the subspace fit, frames x pose_dim for the
  // full-pose fit); empty = closed-form fit of the channel keys (closed_form_fit.h).
  Eigen::MatrixXd initial;
};

enum class FitLinearSolver {
  kAuto,                  // sparse normal Cholesky (SuiteSparse, else Eigen sparse), else dense QR
  kSparseNormalCholesky,  // fails with kUnsupported when Ceres has no sparse library
  kDenseQr,               // for small problems and as a cross-check
};

struct PcaFitOptions {
  double key_sigma_deg = 1.0;        // s_key: tolerance of rotation keys (degrees, > 0)
  double root_key_sigma = 1.0;       // tolerance of root-feature keys (weighted, cm-like units, > 0)
  // s_pos: tolerance of position keys (cm, > 0). At 1 cm the prior pulls keyed feet a
  // centimetre or two off their keys; a quarter of that keeps them within 1 cm (docs/pca.md).
  double position_sigma_cm = 0.25;
  double position_huber_cm = 0.0;    // > 0: Huber loss at this scale (cm) for inconsistent position keys
  double guide_sigma_deg = 10.0;     // s_guide (degrees, > 0)
  double guide_root_sigma = 10.0;    // guide tolerance of root features (weighted units, > 0)
  double prior_scale = 1.0;          // multiplies the prior residuals (>= 0; 0 = no prior)
  double smoothness_scale = 1.0;     // multiplies the smoothness residuals (>= 0; 0 = none)
  int max_iterations = 50;           // Levenberg-Marquardt iterations (>= 1)
  double function_tolerance = 1e-10; // Ceres relative cost change for convergence (> 0)
  int num_threads = 0;               // 0 = all hardware threads
  FitLinearSolver linear_solver = FitLinearSolver::kAuto;

  // kInvalidArgument naming the field.
  Status Validate() const;
};

// The Ceres solver summary as plain data (names as in ceres::TerminationType).
struct SolverReport {
  std::string termination_type;  // CONVERGENCE, NO_CONVERGENCE, FAILURE, USER_SUCCESS, USER_FAILURE
  bool converged = false;        // CONVERGENCE or USER_SUCCESS
  int iterations = 0;            // LM steps taken (linear solves); a linear problem needs 1
  double initial_cost = 0.0;     // Ceres cost = 0.5 * sum of squared residuals
  double final_cost = 0.0;
  double solve_time_s = 0.0;     // Ceres total time
  double preprocess_time_s = 0.0;       // problem analysis and ordering inside Solve()
  double jacobian_time_s = 0.0;         // residual and Jacobian evaluation
  double linear_solver_time_s = 0.0;    // factorisations
  std::string message;
  std::string linear_solver;     // e.g. "SPARSE_NORMAL_CHOLESKY (SUITE_SPARSE)"
  int num_parameters = 0;        // free parameters (constant blocks excluded)
  int num_residuals = 0;
  int num_residual_blocks = 0;
};

struct PcaFitResult {
  Eigen::MatrixXd coefficients;  // frames x K (full-pose: the projection of poses)
  Eigen::MatrixXd poses;         // frames x pose_dim fitted weighted pose vectors
  SolverReport report;
  double initial_guess_s = 0.0;  // closed-form start (wall clock, seconds)
  double build_s = 0.0;          // residual blocks and problem set-up
  double solve_s = 0.0;          // Ceres Solve() call
};

// Subspace fit. Errors: invalid options/model/problem (kInvalidArgument, naming the key or
// field), no sparse library for kSparseNormalCholesky (kUnsupported), solver failure or
// non-finite result (kNumericalFailure). NO_CONVERGENCE within max_iterations is not an
// error: the result is returned with report.converged = false.
Result<PcaFitResult> FitPcaToKeys(const PcaModel& model, const PcaKeyProblem& problem, const PcaFitOptions& options);

// Full-pose variant: channel keys hold exactly (their joint blocks are constant). A joint's
// three channels (and the root features) must be keyed together at a frame. Rotation keys
// are not accepted here (give keys as channel values); position keys are.
Result<PcaFitResult> FitFullPoseToKeys(const PcaModel& model, const PcaKeyProblem& problem,
                                       const PcaFitOptions& options);

// The objective of FitPcaToKeys (Ceres cost: half the sum of squared residuals) at the given
// coefficients; for reports and for checking the solver against an independent solve.
Result<double> SubspaceFitCost(const PcaModel& model, const PcaKeyProblem& problem, const PcaFitOptions& options,
                               const Eigen::MatrixXd& coefficients);

}  // namespace mocapfill
