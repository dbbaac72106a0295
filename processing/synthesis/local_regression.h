// Local linear regression over a fragment's candidates (Cleveland 1979; the local models of
// Chai and Hodgins 2005 fill a full pose from a few control signals the same way). The
// weighted average of the candidates is the kernel estimate of what the sketch fragment
// carries; where the candidates' matching features vary systematically with what they carry
// (a wider step, a wider arm swing), a linear fit over the candidates corrects the average
// towards the sketch's own features. The fit is expressed as new weights of the same
// candidates (its equivalent kernel), so the blend, its time-stretching, cross-fades and the
// voted contacts all use it unchanged.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace mocapfill {

// rows: the candidates' matching features (one row each), query: the sketch fragment's,
// weights: the kernel weights (summing to 1). Returns w_k (1 + (x_k - x̄)ᵀ (Xᵀ W X + λ I)⁻¹
// (q - x̄)), which also sum to 1, with λ = ridge times the candidates' total weighted variance.
std::vector<double> LocalLinearWeights(const Eigen::MatrixXf& rows, const Eigen::VectorXf& query,
                                       const std::vector<double>& weights, double ridge);

}  // namespace mocapfill
