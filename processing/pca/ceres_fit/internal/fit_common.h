// Pieces shared by the subspace and full-pose Ceres fits: problem validation, solver
// options, the summary as plain data, and building the forward-kinematics functor of a
// position key. Internal: include only from processing/pca/*.cc.
#pragma once

#include <ceres/ceres.h>

#include <functional>
#include <string>

#include "processing/pca/ceres_fit/internal/kinematic_costs.h"
#include "processing/pca/ceres_fit/pca_fit.h"

namespace mocapfill::pca_internal {

// DynamicAutoDiffCostFunction stride: derivatives computed per pass. 8 evaluates a
// 30-coefficient block in 4 passes and a 6-joint full-pose chain (18 parameters) in 3.
constexpr int kAutoDiffStride = 8;

// Checks sizes, indices and finiteness of everything in `problem` against the model.
// `initial_cols` is the expected column count of problem.initial (K or pose_dim).
Status ValidateKeyProblem(const PcaModel& model, const PcaKeyProblem& problem, int initial_cols);

// Ceres options for `options` (LM, chosen linear solver, silent). kUnsupported when a
// sparse solver was requested and Ceres has no sparse library.
Result<ceres::Solver::Options> MakeSolverOptions(const PcaFitOptions& options);

SolverReport MakeReport(const ceres::Solver::Summary& summary, const ceres::Solver::Options& options);

// Solves `problem`, timing the solve (solve_s) and keeping its summary as plain data (report);
// kNumericalFailure naming `fit` ("PCA fit", "full-pose PCA fit") when Ceres fails.
Status SolveFit(const ceres::Solver::Options& options, const std::string& fit, ceres::Problem& problem,
                double& solve_s, SolverReport& report);

// Maps a model joint to where its channels live (subspace coefficients or a joint block).
using SourceFactory = std::function<JointSource(int joint)>;

// The FK functor of one position key (the chain from the anchor to the keyed joint's
// parent, sources from `make_source`); block indices are assigned by the factory.
PositionKeyFunctor MakePositionFunctor(const PcaModel& model, const PcaKeyProblem& problem, const PositionKey& key,
                                       double sigma_cm, const SourceFactory& make_source);

// The anchor-to-parent chain of model joints for a key on `joint` (anchor first).
std::vector<int> KinematicChain(const PcaModel& model, const FitKinematics& kinematics, int joint);

// HuberLoss for position residuals already divided by sigma, or nullptr.
ceres::LossFunction* MakePositionLoss(const PcaFitOptions& options);

}  // namespace mocapfill::pca_internal
