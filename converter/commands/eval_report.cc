#include "converter/commands/eval_report.h"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

namespace mocapfill::cli {

namespace {

using Json = nlohmann::ordered_json;

Json EvalMetricsJson(const FillMetrics& m) {
  return {{"mpjpe_unkeyed_cm", m.mpjpe_unkeyed_cm},
          {"mpjpe_keyed_between_cm", m.mpjpe_keyed_between_cm},
          {"angle_unkeyed_deg", m.angle_unkeyed_deg},
          {"npss", m.npss},
          {"jitter_ratio", m.jitter_ratio},
          {"foot_skate_cm_per_s", m.foot_skate_cm_per_s},
          {"foot_skate_share", m.foot_skate_share},
          {"foot_slide_cm_per_s", m.foot_slide_cm_per_s},
          {"foot_contact_frames", m.foot_contact_frames},
          {"penetration_max_cm", m.penetration_max_cm},
          {"penetration_mean_cm", m.penetration_mean_cm},
          {"floor_glide_cm_per_s", m.floor_glide_cm_per_s},
          {"floor_steps", m.floor_steps},
          {"capture_floor_glide_cm_per_s", m.capture_floor_glide_cm_per_s},
          {"capture_floor_steps", m.capture_floor_steps},
          {"foot_peak_ratio", m.foot_peak_ratio},
          {"key_error_mean_deg", m.key_error_mean_deg},
          {"key_error_max_deg", m.key_error_max_deg},
          {"bone_length_error", m.bone_length_error}};
}

Json EvalIntervalJson(const Interval& i) { return {{"lo", i.lo}, {"hi", i.hi}}; }

Interval IntervalOf(const SummaryRow& row, const std::string& metric) {
  for (const MetricInterval& m : row.intervals)
    if (m.metric == metric) return m.interval;
  return {};
}

// The halves in the order the results hold them.
std::vector<std::string> ReportedHalves(const EvaluationResult& r) {
  std::vector<std::string> halves;
  for (const SummaryRow& row : r.summary)
    if (std::find(halves.begin(), halves.end(), row.half) == halves.end()) halves.push_back(row.half);
  return halves;
}

std::string JoinNames(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
  return out;
}

int FoldsOfHalf(const EvaluationResult& r, const std::string& half) {
  std::vector<std::string> folds;
  for (const ClipScore& s : r.scores)
    if (s.half == half && std::find(folds.begin(), folds.end(), s.fold) == folds.end()) folds.push_back(s.fold);
  return static_cast<int>(folds.size());
}

std::string WithInterval(double value, const Interval& i, int decimals) {
  const int bounds = std::max(1, decimals - 1);  // the interval's ends are less precise than the mean
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%.*f [%.*f, %.*f]", decimals, value, bounds, i.lo, bounds, i.hi);
  return buffer;
}

void PrintProtocolHeader(const EvaluationResult& r, const EvalReportContext& c) {
  if (!c.against.empty()) {
    std::printf("against a fixed database: keep %s every %d frames\n", c.keep.c_str(), c.every);
  } else if (c.split == Split::kNone) {
    std::printf("leave-one-%s-out: %d folds, keep %s every %d frames\n", c.loso.c_str(), r.folds, c.keep.c_str(),
                c.every);
  } else {
    std::printf("split-half leave-one-%s-out (%s values sorted by name, dealt alternately): %d folds run, keep %s "
                "every %d frames\n",
                c.loso.c_str(), c.loso.c_str(), r.folds, c.keep.c_str(), c.every);
    std::printf("  tuning half (%zu): %s; each held out against the other tuning %s values only\n",
                r.halves.tuning.size(), JoinNames(r.halves.tuning).c_str(), c.loso.c_str());
    std::printf("  reporting half (%zu): %s; each held out against every other %s value of both halves\n",
                r.halves.reporting.size(), JoinNames(r.halves.reporting).c_str(), c.loso.c_str());
  }
  std::printf("intervals: %.0f %% percentile bootstrap, held-out folds resampled, then clips within each (%d "
              "resamples, seed %llu); below mean: unkeyed MPJPE below mean's, paired by clip\n",
              100.0 * c.bootstrap.level, c.bootstrap.resamples,
              static_cast<unsigned long long>(c.bootstrap.seed));
}

void PrintHalfTable(const EvaluationResult& r, const std::string& half) {
  std::printf("%-11s %-13s %5s %-22s %-22s %9s %7s %7s %7s %-20s %6s %-18s %-18s %7s %-19s %8s %-16s %8s %8s %6s "
              "%8s\n",
              "category", "method", "clips", "unkeyed cm", "below mean %", "keyed-btw", "angle", "NPSS", "jitter",
              "skate cm/s", "skate%", "slide cm/s", "pen-max cm", "pen-avg", "glide cm/s", "capture", "foot peak",
              "key-mean", "key-max", "poor%", "ms/fill");
  for (const char* category : {"locomotion", "gestures", "all"})
    for (const SummaryRow& row : r.summary) {
      if (row.half != half || row.category != category) continue;
      const FillMetrics& m = row.mean;
      const std::string below =
          row.has_below_mean ? WithInterval(row.below_mean.percent, row.below_mean.interval, 1) : "-";
      std::printf("%-11s %-13s %5d %-22s %-22s %9.3f %7.2f %7.4f %7.3f %-20s %6.1f %-18s %-18s %7.2f %-19s %8.1f "
                  "%-16s %8.4f %8.4f %6.1f %8.1f\n",
                  category, row.method.c_str(), row.clips,
                  WithInterval(m.mpjpe_unkeyed_cm, IntervalOf(row, "mpjpe_unkeyed_cm"), 3).c_str(), below.c_str(),
                  m.mpjpe_keyed_between_cm, m.angle_unkeyed_deg, m.npss, m.jitter_ratio,
                  WithInterval(m.foot_skate_cm_per_s, IntervalOf(row, "foot_skate_cm_per_s"), 2).c_str(),
                  100.0 * m.foot_skate_share,
                  WithInterval(m.foot_slide_cm_per_s, IntervalOf(row, "foot_slide_cm_per_s"), 2).c_str(),
                  WithInterval(m.penetration_max_cm, IntervalOf(row, "penetration_max_cm"), 2).c_str(),
                  m.penetration_mean_cm,
                  WithInterval(m.floor_glide_cm_per_s, IntervalOf(row, "floor_glide_cm_per_s"), 1).c_str(),
                  m.capture_floor_glide_cm_per_s,
                  WithInterval(m.foot_peak_ratio, IntervalOf(row, "foot_peak_ratio"), 2).c_str(),
                  m.key_error_mean_deg, m.key_error_max_deg,
                  100.0 * row.poorly_covered_share,
                  1000.0 * row.fill_seconds);
    }
  for (const AboveMeanCount& count : r.above_mean)
    if (count.half == half)
      std::printf("per fold: %s above mean in %d of %d (fold, category) cells\n", count.method.c_str(), count.above,
                  count.cells);
}

// Below-mean columns are headed "<method> below mean %" (positive: below mean); every column is
// as wide as its heading.
void PrintFoldTable(const EvaluationResult& r, const std::string& half) {
  auto width = [](const std::string& heading) { return std::max<int>(10, static_cast<int>(heading.size())); };
  bool header = false;
  for (const FoldCell& cell : r.fold_cells) {
    if (cell.half != half) continue;
    if (!header) {
      std::printf("%-14s %-11s %5s", "fold", "category", "clips");
      for (const FoldMethodMean& m : cell.methods) std::printf(" %*s", width(m.method + " cm"), (m.method + " cm").c_str());
      for (const FoldMethodMean& m : cell.methods)
        if (m.method != kBaselineMethod)
          std::printf(" %*s", width(m.method + " below mean %"), (m.method + " below mean %").c_str());
      std::printf("\n");
      header = true;
    }
    std::printf("%-14s %-11s %5d", cell.fold.c_str(), cell.category.c_str(), cell.clips);
    for (const FoldMethodMean& m : cell.methods) std::printf(" %*.3f", width(m.method + " cm"), m.mean.mpjpe_unkeyed_cm);
    for (const FoldMethodMean& m : cell.methods)
      if (m.method != kBaselineMethod) std::printf(" %*.1f", width(m.method + " below mean %"), m.below_mean_pct);
    std::printf("\n");
  }
}

Json SummaryJson(const SummaryRow& row) {
  Json e = {{"half", row.half}, {"method", row.method}, {"category", row.category}, {"clips", row.clips}};
  e["metrics"] = EvalMetricsJson(row.mean);
  Json intervals = Json::object();
  for (const MetricInterval& m : row.intervals) intervals[m.metric] = EvalIntervalJson(m.interval);
  e["intervals"] = intervals;
  e["below_mean"] = row.has_below_mean ? Json{{"pct", row.below_mean.percent},
                                              {"lo", row.below_mean.interval.lo},
                                              {"hi", row.below_mean.interval.hi}}
                                       : Json(nullptr);
  e["coverage"] = {{"median_unexplained", row.coverage_median_unexplained},
                   {"poorly_covered_share", row.poorly_covered_share}};
  e["fill_seconds"] = row.fill_seconds;
  e["seconds_per_second"] = row.seconds_per_s;
  return e;
}

Json FoldCellJson(const FoldCell& cell, const std::string& default_method) {
  Json methods = Json::array();
  Json default_entry = nullptr;
  bool has_baseline = false;
  for (const FoldMethodMean& m : cell.methods) has_baseline = has_baseline || m.method == kBaselineMethod;
  for (const FoldMethodMean& m : cell.methods) {
    Json below = has_baseline ? Json(m.below_mean_pct) : Json(nullptr);
    methods.push_back({{"method", m.method}, {"metrics", EvalMetricsJson(m.mean)}, {"below_mean_pct", below}});
    if (m.method == default_method && has_baseline && m.method != kBaselineMethod)
      default_entry = {{"method", m.method}, {"below_mean_pct", m.below_mean_pct}, {"above_mean", m.below_mean_pct < 0.0}};
  }
  return {{"half", cell.half}, {"fold", cell.fold},       {"category", cell.category},
          {"clips", cell.clips}, {"methods", methods}, {"default_vs_mean", default_entry}};
}

}  // namespace

void PrintEvalTable(const EvaluationResult& r, const EvalReportContext& context) {
  PrintProtocolHeader(r, context);
  for (const std::string& half : ReportedHalves(r)) {
    if (half != kNoHalf)
      std::printf("\n%s half: %d folds\n", half.c_str(), FoldsOfHalf(r, half));
    PrintHalfTable(r, half);
    if (context.by_fold) PrintFoldTable(r, half);
  }
}

void PrintEvalJson(const EvaluationResult& r, const EvalReportContext& c) {
  Json out;
  const bool loso = c.against.empty();
  out["protocol"] = {{"loso", loso ? Json(c.loso) : Json(nullptr)},
                     {"against", c.against},
                     {"scenario", c.scenario.empty() ? Json(nullptr) : Json(c.scenario)},
                     {"keep", c.keep},
                     {"every", c.every},
                     {"folds", r.folds},
                     {"split", loso ? Json(SplitName(c.split)) : Json(nullptr)},
                     {"halves", loso ? Json{{"tuning", r.halves.tuning}, {"reporting", r.halves.reporting}}
                                     : Json(nullptr)},
                     {"bootstrap", {{"resamples", c.bootstrap.resamples},
                                    {"seed", c.bootstrap.seed},
                                    {"level", c.bootstrap.level},
                                    {"unit", "folds, then clips within each"}}},
                     {"default_method", c.default_method}};
  Json summary = Json::array();
  for (const SummaryRow& row : r.summary) summary.push_back(SummaryJson(row));
  out["summary"] = summary;
  Json above = Json::array();
  for (const AboveMeanCount& a : r.above_mean)
    above.push_back({{"half", a.half}, {"method", a.method}, {"cells", a.cells}, {"above", a.above}});
  out["above_mean"] = above;
  Json folds = Json::array();
  for (const FoldCell& cell : r.fold_cells) folds.push_back(FoldCellJson(cell, c.default_method));
  out["fold_cells"] = folds;
  Json clips = Json::array();
  for (const ClipScore& s : r.scores)
    clips.push_back({{"clip", s.clip}, {"half", s.half}, {"fold", s.fold}, {"category", s.category},
                     {"method", s.method}, {"metrics", EvalMetricsJson(s.metrics)},
                     {"coverage", {{"median_unexplained", s.coverage_median_unexplained},
                                   {"poorly_covered_share", s.poorly_covered_share}}},
                     {"fill_seconds", s.fill_seconds}});
  out["clips"] = clips;
  std::printf("%s\n", out.dump(2).c_str());
}

}  // namespace mocapfill::cli
