#include "processing/texturing/activity_gain.h"

#include <algorithm>
#include <cmath>

#include "processing/filtering/window_mean.h"

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
  return WindowMean(speed, half);
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
