#include "processing/filtering/window_mean.h"

#include <algorithm>

namespace mocapfill {

Eigen::MatrixXd WindowMean(const Eigen::MatrixXd& m, int half) {
  const Eigen::Index frames = m.rows();
  // Running sums make every window one subtraction.
  Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(frames + 1, m.cols());
  for (Eigen::Index t = 0; t < frames; ++t) sums.row(t + 1) = sums.row(t) + m.row(t);
  Eigen::MatrixXd mean(frames, m.cols());
  for (Eigen::Index t = 0; t < frames; ++t) {
    const Eigen::Index t0 = std::max<Eigen::Index>(0, t - half), t1 = std::min<Eigen::Index>(frames - 1, t + half);
    mean.row(t) = (sums.row(t1 + 1) - sums.row(t0)) / static_cast<double>(t1 - t0 + 1);
  }
  return mean;
}

}  // namespace mocapfill
