// Joint-correlation table (thesis section 4.7 and figure 4.4, pelvis against hip): for
// every channel pair (a, b) the Pearson correlation of a band-pass signal of a with the same
// band of b shifted by a lag tau, maximised in |corr| over |tau| <= max lag. The hierarchical
// fill method ranks driven channels by |corr| and uses the sign and lag when matching.
#pragma once

#include <Eigen/Core>
#include <span>
#include <vector>

#include "processing/core/status.h"

namespace mocapfill {

// A run of consecutive rows of one clip inside a concatenated matrix. Lagged pairs never
// cross from one segment into the next.
struct FrameSegment {
  int first_row = 0;
  int num_rows = 0;
};

struct CorrelationEntry {
  float max_abs = 0.0f;  // max over lags of |corr|, in [0, 1]
  float value = 0.0f;    // the signed correlation at that lag
  int lag_frames = 0;    // tau: corr(a[t], b[t + tau]); tau > 0 means b follows a
};

struct CorrelationTable {
  int num_channels = 0;
  int max_lag_frames = 0;
  int band = -1;            // Laplacian band the table was computed on (-1: raw signals)
  double rate_hz = 0.0;     // sample rate of the signals (lag_frames / rate_hz = seconds)
  std::vector<CorrelationEntry> entries;  // row-major, num_channels x num_channels

  const CorrelationEntry& at(int a, int b) const { return entries[static_cast<size_t>(a) * num_channels + b]; }
  bool empty() const { return entries.empty(); }
};

// Computes the table over all segments of `signals` (rows = frames, columns = channels).
// Means and standard deviations are taken over all rows; a channel whose standard deviation
// is below 1e-9 (e.g. a joint that never moves) correlates 0 with everything. Each lag's sum
// runs over the row pairs (t, t + tau) that lie inside one segment; rows outside every
// segment take part in no pair. The diagonal at lag 0 is
// 1 for moving channels. Entry (b, a) mirrors (a, b) with the lag negated. Work is split over
// `threads` threads (0 = hardware concurrency); the result does not depend on the split.
// Errors: segments outside the matrix or overlapping, negative max lag (kInvalidArgument).
Result<CorrelationTable> ComputeCorrelationTable(const Eigen::MatrixXf& signals,
                                                 std::span<const FrameSegment> segments, int max_lag_frames,
                                                 int threads = 0);

}  // namespace mocapfill
