// What the evaluation reports from its per-clip scores: means per (half, method, category)
// with bootstrap intervals (held-out folds resampled, then clips within each) and the paired
// relative difference to the `mean` baseline, and
// per-fold cells, so that "never above `mean` in any style" can be checked cell by cell.
#pragma once

#include <string>
#include <vector>

#include "processing/evaluation/bootstrap.h"
#include "processing/evaluation/metrics.h"
#include "processing/fill/fill_options.h"

namespace mocapfill {

struct NamedMethod {
  std::string name;
  FillOptions options;
};

// The method every other one is compared against: the mean pose for unkeyed joints.
inline constexpr const char* kBaselineMethod = "mean";

struct ClipScore {
  std::string clip;
  std::string fold;
  std::string category;  // "locomotion" or "gestures"
  std::string method;
  FillMetrics metrics;
  double fill_seconds = 0.0;
  double seconds_per_s = 0.0;  // fill time per second of animation
  double coverage_median_unexplained = 0.0;  // fragment methods: median FragmentCoverage::unexplained
  double poorly_covered_share = 0.0;   // share of the sketch's frames in poorly covered stretches
  std::string half = "all";            // fold_plan.h: "tuning", "reporting" or "all"
};

struct MetricInterval {
  std::string metric;  // AveragedMetricFields() name
  Interval interval;
};

struct SummaryRow {
  std::string half;      // as ClipScore::half
  std::string method;
  std::string category;  // "locomotion", "gestures", "all"
  int clips = 0;
  FillMetrics mean;      // every metric averaged over clips
  std::vector<MetricInterval> intervals;  // one per AveragedMetricFields() entry
  // MPJPE of the unkeyed joints below `mean`'s, in percent, paired by clip (only when `mean`
  // was scored on the same clips).
  bool has_below_mean = false;
  RelativeDifference below_mean;
  double coverage_median_unexplained = 0.0;  // averaged over clips
  double poorly_covered_share = 0.0;
  double fill_seconds = 0.0;
  double seconds_per_s = 0.0;
};

struct FoldMethodMean {
  std::string method;
  FillMetrics mean;             // averaged over the cell's clips
  double below_mean_pct = 0.0;  // unkeyed MPJPE below `mean`'s in the cell (0 without `mean`)
};

// One held-out fold and category (locomotion or gestures) with the clips it has.
struct FoldCell {
  std::string half;
  std::string fold;
  std::string category;
  int clips = 0;
  std::vector<FoldMethodMean> methods;  // in method order
};

// How many cells of a half a method's unkeyed MPJPE is above `mean`'s.
struct AboveMeanCount {
  std::string half;
  std::string method;
  int cells = 0;
  int above = 0;
};

// Rows per half (in order of first appearance), method (in method order) and category
// (locomotion, gestures, all), skipping empty ones.
std::vector<SummaryRow> Summarise(const std::vector<ClipScore>& scores, const std::vector<NamedMethod>& methods,
                                  const BootstrapOptions& bootstrap = {});

// Cells in order of first appearance of (half, fold), locomotion before gestures.
std::vector<FoldCell> SummariseFolds(const std::vector<ClipScore>& scores, const std::vector<NamedMethod>& methods);

// Per half and method other than `mean`; empty when `mean` is not among the methods.
std::vector<AboveMeanCount> CountAboveMean(const std::vector<FoldCell>& cells);

}  // namespace mocapfill
