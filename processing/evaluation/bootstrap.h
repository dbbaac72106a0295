// Percentile bootstrap intervals for means over clips: how far a mean could move if the same
// protocol were run on another draw of clips like these. Resampling is seeded, so a run is
// reproducible and two tables of one run agree.
#pragma once

#include <cstdint>
#include <vector>

namespace mocapfill {

struct BootstrapOptions {
  int resamples = 2000;
  std::uint64_t seed = 15;  // fixed: the same clips give the same interval on every run
  double level = 0.95;      // central coverage of the percentile interval
};

// Which items are drawn together: items of one group (the clips of one held-out style) are not
// independent, so an interval meant for an unseen group resamples groups with replacement
// first, then items with replacement within each drawn group (a two-stage cluster
// bootstrap). Empty: every item is its own group (the plain bootstrap over items).
using BootstrapGroups = std::vector<int>;

struct Interval {
  double lo = 0.0;
  double hi = 0.0;
};

// Interval of the mean of `values`: means of `resamples` draws with replacement of
// values.size() values, cut at the (1 - level) / 2 and (1 + level) / 2 percentiles (linear
// between order statistics). Empty input gives {0, 0}. `groups`, when given, has one entry per
// value.
Interval BootstrapMean(const std::vector<double>& values, const BootstrapOptions& options = {},
                       const BootstrapGroups& groups = {});

// The same for the weighted mean sum(w x) / sum(w) (a figure pooled over frames while clips
// are what is resampled). Requires equal sizes; empty input or zero weights give {0, 0}.
Interval BootstrapWeightedMean(const std::vector<double>& values, const std::vector<double>& weights,
                               const BootstrapOptions& options = {}, const BootstrapGroups& groups = {});

// 100 * (mean(reference) - mean(values)) / mean(reference): how far `values` lie below the
// reference, in percent, with the paired bootstrap interval (each draw resamples indices and
// recomputes both means, so values[i] and reference[i] must belong to the same clip).
// Requires equal sizes; empty input or a zero reference mean gives zeros.
struct RelativeDifference {
  double percent = 0.0;
  Interval interval;
};
RelativeDifference BootstrapPercentBelow(const std::vector<double>& values, const std::vector<double>& reference,
                                         const BootstrapOptions& options = {}, const BootstrapGroups& groups = {});

}  // namespace mocapfill
