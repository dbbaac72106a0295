// A Ceres cost whose residual is affine in its parameter blocks:
//   r = sum_b A_b x_b - offset,
// with constant Jacobians A_b. Every PCA residual except geodesic and position keys is
// of this form (key rotations, prior, smoothness, guide: pca_fit.h), so an
// analytic cost avoids automatic differentiation entirely. Internal: Ceres types must
// not appear in public headers; include only from processing/pca/*.cc.
#pragma once

#include <ceres/cost_function.h>

#include <Eigen/Core>
#include <cstring>
#include <utility>
#include <vector>

namespace mocapfill::pca_internal {

using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

class LinearCost final : public ceres::CostFunction {
 public:
  // blocks[b] is A_b (residuals x size of block b); all have offset.size() rows.
  LinearCost(std::vector<RowMajorMatrix> blocks, Eigen::VectorXd offset)
      : blocks_(std::move(blocks)), offset_(std::move(offset)) {
    set_num_residuals(static_cast<int>(offset_.size()));
    for (const RowMajorMatrix& a : blocks_) mutable_parameter_block_sizes()->push_back(static_cast<int>(a.cols()));
  }

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const override {
    Eigen::Map<Eigen::VectorXd> r(residuals, offset_.size());
    r = -offset_;
    for (size_t b = 0; b < blocks_.size(); ++b) {
      r.noalias() += blocks_[b] * Eigen::Map<const Eigen::VectorXd>(parameters[b], blocks_[b].cols());
      if (jacobians != nullptr && jacobians[b] != nullptr)
        std::memcpy(jacobians[b], blocks_[b].data(), sizeof(double) * blocks_[b].size());
    }
    return true;
  }

 private:
  std::vector<RowMajorMatrix> blocks_;
  Eigen::VectorXd offset_;
};

}  // namespace mocapfill::pca_internal
