#include "processing/synthesis/local_regression.h"

#include <Eigen/Cholesky>
#include <cmath>

namespace mocapfill {

std::vector<double> LocalLinearWeights(const Eigen::MatrixXf& rows, const Eigen::VectorXf& query,
                                       const std::vector<double>& weights, double ridge) {
  const int n = static_cast<int>(rows.rows());
  if (n < 2 || ridge <= 0.0) return weights;
  const Eigen::Map<const Eigen::VectorXd> w(weights.data(), n);
  const Eigen::MatrixXd x = rows.cast<double>();
  const Eigen::RowVectorXd mean = w.transpose() * x;
  const Eigen::MatrixXd centred = x.rowwise() - mean;
  // A = W^1/2 Xc; (AᵀA + λI)⁻¹ u through the n x n system (Woodbury): the features may
  // outnumber the candidates.
  const Eigen::MatrixXd a = w.cwiseSqrt().asDiagonal() * centred;
  const double lambda = ridge * std::max(1e-12, a.squaredNorm());
  const Eigen::VectorXd u = query.cast<double>() - mean.transpose();
  Eigen::MatrixXd gram = a * a.transpose();
  gram.diagonal().array() += lambda;
  const Eigen::VectorXd v = (u - a.transpose() * gram.ldlt().solve(a * u)) / lambda;
  const Eigen::VectorXd gain = centred * v;
  std::vector<double> out(n);
  for (int k = 0; k < n; ++k) out[k] = weights[k] * (1.0 + gain[k]);
  return out;
}

}  // namespace mocapfill
