#include "processing/analysis/correlation.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <thread>

namespace mocapfill {

namespace {

constexpr double kStillStd = 1e-9;  // a channel with less spread than this never moves

// Standardised copy (zero mean, unit population std over all rows); still channels become 0.
Eigen::MatrixXf Standardise(const Eigen::MatrixXf& signals) {
  Eigen::MatrixXf z(signals.rows(), signals.cols());
  const double n = static_cast<double>(signals.rows());
  for (Eigen::Index c = 0; c < signals.cols(); ++c) {
    const Eigen::VectorXd x = signals.col(c).cast<double>();
    const double mean = x.sum() / n;
    const double std = std::sqrt((x.array() - mean).square().sum() / n);
    if (std < kStillStd) {
      z.col(c).setZero();
    } else {
      z.col(c) = ((x.array() - mean) / std).cast<float>();
    }
  }
  return z;
}

// S(a, b) = sum over segments and t of z_a[t] * z_b[t + lag] / (number of pairs). One large
// product over all rows (rows outside every segment are zero in z), minus the few pairs that
// run from the end of one segment into the rows after it: much faster than a product per
// segment, and exact.
Eigen::MatrixXd LaggedCorrelation(const Eigen::MatrixXf& z, std::span<const FrameSegment> segments, int lag) {
  const Eigen::Index n = z.rows();
  Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(z.cols(), z.cols());
  if (lag >= n) return sum;
  sum = (z.topRows(n - lag).transpose() * z.bottomRows(n - lag)).cast<double>();
  long pairs = 0;
  for (const FrameSegment& s : segments) {
    pairs += std::max(0, s.num_rows - lag);
    const int end = s.first_row + s.num_rows;
    for (int t = std::max(s.first_row, end - lag); t < end && t + lag < n; ++t)
      sum -= (z.row(t).transpose() * z.row(t + lag)).cast<double>();
  }
  if (pairs > 0) sum /= static_cast<double>(pairs);
  return sum;
}

}  // namespace

Result<CorrelationTable> ComputeCorrelationTable(const Eigen::MatrixXf& signals,
                                                 std::span<const FrameSegment> segments, int max_lag_frames,
                                                 int threads) {
  if (max_lag_frames < 0) return InvalidArgument("correlation: max lag must be >= 0");
  std::vector<FrameSegment> sorted(segments.begin(), segments.end());
  std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.first_row < b.first_row; });
  for (size_t i = 0; i < sorted.size(); ++i) {
    const FrameSegment& s = sorted[i];
    if (s.first_row < 0 || s.num_rows < 0 || s.first_row + s.num_rows > signals.rows())
      return InvalidArgument("correlation: segment " + std::to_string(i) + " lies outside the signal matrix");
    if (i > 0 && sorted[i - 1].first_row + sorted[i - 1].num_rows > s.first_row)
      return InvalidArgument("correlation: segments overlap");
  }
  if (!signals.allFinite()) return InvalidArgument("correlation: signals contain a non-finite value");

  Eigen::MatrixXf z = Standardise(signals);
  // Rows outside every segment take no part in any pair.
  std::vector<bool> covered(signals.rows(), false);
  for (const FrameSegment& s : sorted) std::fill_n(covered.begin() + s.first_row, s.num_rows, true);
  for (Eigen::Index r = 0; r < z.rows(); ++r)
    if (!covered[r]) z.row(r).setZero();
  std::vector<Eigen::MatrixXd> by_lag(max_lag_frames + 1);
  // Lags are independent: each worker takes every `workers`-th lag.
  const int workers =
      std::max(1, std::min(threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency()), max_lag_frames + 1));
  std::vector<std::thread> pool;
  for (int w = 0; w < workers; ++w)
    pool.emplace_back([&, w] {
      for (int lag = w; lag <= max_lag_frames; lag += workers) by_lag[lag] = LaggedCorrelation(z, sorted, lag);
    });
  for (std::thread& t : pool) t.join();

  CorrelationTable table;
  const int channels = static_cast<int>(signals.cols());
  table.num_channels = channels;
  table.max_lag_frames = max_lag_frames;
  table.entries.resize(static_cast<size_t>(channels) * channels);
  for (int a = 0; a < channels; ++a) {
    for (int b = 0; b < channels; ++b) {
      CorrelationEntry best;
      // Lag 0 first, then +-1, +-2, ...: on a tie the shorter lag wins.
      for (int step = 0; step <= 2 * max_lag_frames; ++step) {
        const int lag = (step % 2 == 1) ? (step + 1) / 2 : -(step / 2);
        const double c = lag >= 0 ? by_lag[lag](a, b) : by_lag[-lag](b, a);
        const float value = static_cast<float>(std::clamp(c, -1.0, 1.0));
        if (std::abs(value) > best.max_abs) best = {std::abs(value), value, lag};
      }
      table.entries[static_cast<size_t>(a) * channels + b] = best;
    }
  }
  return table;
}

}  // namespace mocapfill
