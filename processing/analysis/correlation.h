// Joint-correlation table (thesis section 4.7 and figure 4.4, pelvis against hip): for
// every channel pair (a, b) the Pearson correlation of a band-pass signal of a with the same
// band of b shifted by a lag tau, maximised in |corr| over |tau| <= max lag. The hierarchical
// fill method ranks driven channels by |corr| and uses the sign and lag when matching.
#pragma once

#include <Eigen/Core>
#include <span>

#include "processing/core/correlation_table.h"
#include "processing/core/signal_layout.h"
#include "processing/core/status.h"

namespace mocapfill {

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
