#include "processing/pca/pca_projection.h"

#include <algorithm>
#include <cmath>

namespace mocapfill {

Eigen::MatrixXd ProjectOntoModel(const PcaModel& model, const Eigen::MatrixXd& vectors, int components) {
  Eigen::MatrixXd coefficients = (vectors.rowwise() - model.mean.transpose()) * model.components;
  if (components > 0 && components < coefficients.cols())
    coefficients.rightCols(coefficients.cols() - components).setZero();
  return coefficients;
}

Eigen::MatrixXd ReconstructFromModel(const PcaModel& model, const Eigen::MatrixXd& coefficients) {
  return (coefficients * model.components.transpose()).rowwise() + model.mean.transpose();
}

double ExplainedVarianceRatio(const PcaModel& model, int components) {
  const double total = model.spectrum.sum();
  if (!(total > 0.0)) return 0.0;
  const int n = std::clamp(components, 0, static_cast<int>(model.spectrum.size()));
  return std::min(1.0, model.spectrum.head(n).sum() / total);
}

double ReconstructionRms(const PcaModel& model, const Eigen::MatrixXd& vectors, int components) {
  if (vectors.size() == 0) return 0.0;
  // No components means "mean only" here (unlike ProjectOntoModel, where 0 means all).
  const Eigen::MatrixXd error =
      components <= 0 ? Eigen::MatrixXd(vectors.rowwise() - model.mean.transpose())
                      : Eigen::MatrixXd(vectors - ReconstructFromModel(model, ProjectOntoModel(model, vectors, components)));
  return std::sqrt(error.squaredNorm() / static_cast<double>(error.size()));
}

}  // namespace mocapfill
