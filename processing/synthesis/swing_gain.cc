#include "processing/synthesis/swing_gain.h"

#include "processing/filtering/window_mean.h"

namespace mocapfill {

void ScaleSwing(const std::vector<int>& channels, double gain, int half_window, Eigen::MatrixXd& out) {
  if (channels.empty() || gain == 1.0) return;
  Eigen::MatrixXd picked(out.rows(), static_cast<Eigen::Index>(channels.size()));
  for (size_t k = 0; k < channels.size(); ++k) picked.col(static_cast<Eigen::Index>(k)) = out.col(channels[k]);
  const Eigen::MatrixXd mean = WindowMean(picked, half_window);
  for (size_t k = 0; k < channels.size(); ++k) {
    const Eigen::Index col = static_cast<Eigen::Index>(k);
    out.col(channels[k]) = mean.col(col) + gain * (picked.col(col) - mean.col(col));
  }
}

}  // namespace mocapfill
