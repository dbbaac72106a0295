#include "processing/texturing/activity_gain.h"

#include <algorithm>
#include <cmath>

namespace mocapfill {

namespace {

// Mean absolute central-difference speed of every column over [t - half, t + half].
Eigen::MatrixXd WindowedSpeed(const Eigen::MatrixXd& m, double rate_hz, int half) {
  const Eigen::Index frames = m.rows();
  Eigen::MatrixXd speed(frames, m.cols());
  for (Eigen::Index t = 0; t < frames; ++t) {
    const Eigen::Index t0 = std::max<Eigen::Index>(0, t - 1), t1 = std::min(frames - 1, t + 1);
    speed.row(t) = (m.row(t1) - m.row(t0)).cwiseAbs() * (rate_hz / static_cast<double>(t1 - t0));
  }
  // Running sums make every window one subtraction.
  Eigen::MatrixXd sums = Eigen::MatrixXd::Zero(frames + 1, m.cols());
  for (Eigen::Index t = 0; t < frames; ++t) sums.row(t + 1) = sums.row(t) + speed.row(t);
  Eigen::MatrixXd mean(frames, m.cols());
  for (Eigen::Index t = 0; t < frames; ++t) {
    const Eigen::Index t0 = std::max<Eigen::Index>(0, t - half), t1 = std::min<Eigen::Index>(frames - 1, t + half);
    mean.row(t) = (sums.row(t1 + 1) - sums.row(t0)) / static_cast<double>(t1 - t0 + 1);
  }
  return mean;
}

}  // namespace

Eigen::MatrixXd ActivityGain(const Eigen::MatrixXd& sketch, const Eigen::MatrixXd& source, double rate_hz,
                             double window_s, double floor_per_s) {
  if (sketch.rows() < 2) return Eigen::MatrixXd::Ones(sketch.rows(), sketch.cols());
  const int half = std::max(1, static_cast<int>(std::lround(0.5 * window_s * rate_hz)));
  const Eigen::MatrixXd a = WindowedSpeed(sketch, rate_hz, half);
  const Eigen::MatrixXd b = WindowedSpeed(source, rate_hz, half);
  return ((a.array() + floor_per_s) / (b.array() + floor_per_s)).min(1.0).matrix();
}

}  // namespace mocapfill
