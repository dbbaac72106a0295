#include "processing/analysis/band_energy.h"

namespace mocapfill {

Eigen::MatrixXd BandEnergies(const Pyramid& pyramid, const std::vector<std::vector<int>>& column_groups) {
  const int levels = pyramid.levels();
  Eigen::MatrixXd energies = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(column_groups.size()), levels + 1);
  const double frames = static_cast<double>(pyramid.residual.rows());
  if (frames == 0) return energies;
  for (size_t g = 0; g < column_groups.size(); ++g) {
    for (int c : column_groups[g]) {
      for (int k = 0; k < levels; ++k) energies(g, k) += pyramid.bands[k].col(c).squaredNorm() / frames;
      const Eigen::VectorXd residual = pyramid.residual.col(c);
      energies(g, levels) += (residual.array() - residual.mean()).square().sum() / frames;
    }
  }
  return energies;
}

Eigen::MatrixXd BandEnergyShares(const Eigen::MatrixXd& energies) {
  Eigen::MatrixXd shares = Eigen::MatrixXd::Zero(energies.rows(), energies.cols());
  for (Eigen::Index g = 0; g < energies.rows(); ++g) {
    const double total = energies.row(g).sum();
    if (total > 0.0) shares.row(g) = energies.row(g) / total;
  }
  return shares;
}

}  // namespace mocapfill
