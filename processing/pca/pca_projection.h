// Projection onto and reconstruction from a PcaModel's components,
// and the explained-variance / reconstruction-error figures `pca info` reports.
#pragma once

#include <Eigen/Core>

#include "processing/core/pca_model.h"

namespace mocapfill {

// Coefficients of `vectors` (rows, model.dim() columns): C = (X - mu) U, (rows x K).
// Only the first `components` are used when 0 < components < K (the rest are zero).
Eigen::MatrixXd ProjectOntoModel(const PcaModel& model, const Eigen::MatrixXd& vectors, int components = 0);

// Vectors from coefficients (rows x K): X = mu + C U^T.
Eigen::MatrixXd ReconstructFromModel(const PcaModel& model, const Eigen::MatrixXd& coefficients);

// Share of the total variance carried by the first `components` directions of the full
// spectrum (may exceed the kept K; clamped to the spectrum size), in [0, 1].
double ExplainedVarianceRatio(const PcaModel& model, int components);

// Root-mean-square per-entry error of reconstructing `vectors` from their projection on the
// first `components` kept components (weighted units; cm-like for weighted tangents);
// components <= 0 measures the distance to the mean.
double ReconstructionRms(const PcaModel& model, const Eigen::MatrixXd& vectors, int components);

}  // namespace mocapfill
