#include "processing/evaluation/summary.h"

#include <algorithm>
#include <map>

namespace mocapfill {

namespace {

void AddWeighted(FillMetrics& sum, const FillMetrics& m, double w) {
  for (const MetricField& field : AveragedMetricFields()) sum.*field.field += w * m.*field.field;
  sum.key_error_max_deg = std::max(sum.key_error_max_deg, m.key_error_max_deg);  // worst, not mean
  sum.unkeyed_joints = m.unkeyed_joints;
}

// Foot skating is pooled over the truth's contact frames, and floor glide over the steps on
// the floor: a clip with one contact frame must not weigh as much as a walk with hundreds (the
// per-clip average let single frames of runs dominate it). The count a field is pooled over,
// or null for a plain mean over clips.
long FillMetrics::*PoolingCount(double FillMetrics::*field) {
  if (field == &FillMetrics::foot_skate_cm_per_s || field == &FillMetrics::foot_skate_share ||
      field == &FillMetrics::foot_slide_cm_per_s)
    return &FillMetrics::foot_contact_frames;
  if (field == &FillMetrics::floor_glide_cm_per_s) return &FillMetrics::floor_steps;
  if (field == &FillMetrics::capture_floor_glide_cm_per_s) return &FillMetrics::capture_floor_steps;
  return nullptr;
}

void PoolOverCounts(const std::vector<const ClipScore*>& scores, FillMetrics& mean) {
  for (const MetricField& field : AveragedMetricFields()) {
    long FillMetrics::*count = PoolingCount(field.field);
    if (!count) continue;
    long total = 0;
    double sum = 0.0;
    for (const ClipScore* s : scores) {
      total += s->metrics.*count;
      sum += s->metrics.*field.field * s->metrics.*count;
    }
    mean.*count = total;
    mean.*field.field = total > 0 ? sum / total : 0.0;
  }
}

std::vector<std::string> HalvesInOrder(const std::vector<ClipScore>& scores) {
  std::vector<std::string> halves;
  for (const ClipScore& s : scores)
    if (std::find(halves.begin(), halves.end(), s.half) == halves.end()) halves.push_back(s.half);
  return halves;
}

// The row's scores with, per score, the baseline's score of the same clip (null when missing).
struct RowScores {
  std::vector<const ClipScore*> scores, baseline;
};

RowScores SelectRow(const std::vector<ClipScore>& scores, const std::string& half, const std::string& method,
                 const std::string& category) {
  std::map<std::string, const ClipScore*> baseline;
  for (const ClipScore& s : scores)
    if (s.half == half && s.method == kBaselineMethod) baseline[s.clip] = &s;
  RowScores out;
  for (const ClipScore& s : scores)
    if (s.half == half && s.method == method && (category == "all" || s.category == category)) {
      out.scores.push_back(&s);
      const auto it = baseline.find(s.clip);
      out.baseline.push_back(it == baseline.end() ? nullptr : it->second);
    }
  return out;
}

// Clips of one held-out fold share a style, so they are resampled together (bootstrap.h).
BootstrapGroups FoldGroups(const std::vector<const ClipScore*>& scores) {
  std::map<std::string, int> ids;
  BootstrapGroups groups;
  for (const ClipScore* s : scores) groups.push_back(ids.emplace(s->fold, static_cast<int>(ids.size())).first->second);
  return groups;
}

void AddIntervals(const RowScores& selected, const BootstrapOptions& bootstrap, SummaryRow& row) {
  const BootstrapGroups groups = FoldGroups(selected.scores);
  for (const MetricField& field : AveragedMetricFields()) {
    long FillMetrics::*count = PoolingCount(field.field);
    std::vector<double> values, counts;
    for (const ClipScore* s : selected.scores) {
      values.push_back(s->metrics.*field.field);
      if (count) counts.push_back(static_cast<double>(s->metrics.*count));
    }
    row.intervals.push_back({field.name, count ? BootstrapWeightedMean(values, counts, bootstrap, groups)
                                               : BootstrapMean(values, bootstrap, groups)});
  }
  std::vector<double> values, reference;
  for (size_t i = 0; i < selected.scores.size(); ++i) {
    if (!selected.baseline[i]) return;  // unpaired: no comparison for this row
    values.push_back(selected.scores[i]->metrics.mpjpe_unkeyed_cm);
    reference.push_back(selected.baseline[i]->metrics.mpjpe_unkeyed_cm);
  }
  row.has_below_mean = !values.empty() && row.method != kBaselineMethod;
  row.below_mean = BootstrapPercentBelow(values, reference, bootstrap, groups);
}

}  // namespace

std::vector<SummaryRow> Summarise(const std::vector<ClipScore>& scores, const std::vector<NamedMethod>& methods,
                                  const BootstrapOptions& bootstrap) {
  std::vector<SummaryRow> rows;
  for (const std::string& half : HalvesInOrder(scores))
    for (const NamedMethod& method : methods)
      for (const char* category : {"locomotion", "gestures", "all"}) {
        const RowScores selected = SelectRow(scores, half, method.name, category);
        if (selected.scores.empty()) continue;
        SummaryRow row;
        row.half = half;
        row.method = method.name;
        row.category = category;
        row.clips = static_cast<int>(selected.scores.size());
        const double w = 1.0 / row.clips;
        for (const ClipScore* s : selected.scores) {
          AddWeighted(row.mean, s->metrics, w);
          row.coverage_median_unexplained += w * s->coverage_median_unexplained;
          row.poorly_covered_share += w * s->poorly_covered_share;
          row.fill_seconds += w * s->fill_seconds;
          row.seconds_per_s += w * s->seconds_per_s;
        }
        PoolOverCounts(selected.scores, row.mean);
        AddIntervals(selected, bootstrap, row);
        rows.push_back(row);
      }
  return rows;
}

std::vector<FoldCell> SummariseFolds(const std::vector<ClipScore>& scores, const std::vector<NamedMethod>& methods) {
  std::vector<std::pair<std::string, std::string>> folds;  // (half, fold) in order of appearance
  for (const ClipScore& s : scores)
    if (std::find(folds.begin(), folds.end(), std::make_pair(s.half, s.fold)) == folds.end())
      folds.emplace_back(s.half, s.fold);
  std::vector<FoldCell> cells;
  for (const auto& [half, fold] : folds)
    for (const char* category : {"locomotion", "gestures"}) {
      FoldCell cell{half, fold, category, 0, {}};
      for (const NamedMethod& method : methods) {
        FoldMethodMean entry{method.name, {}, 0.0};
        std::vector<const ClipScore*> mine;
        for (const ClipScore& s : scores)
          if (s.half == half && s.fold == fold && s.category == category && s.method == method.name) mine.push_back(&s);
        const int n = static_cast<int>(mine.size());
        if (n == 0) continue;
        for (const ClipScore* s : mine) AddWeighted(entry.mean, s->metrics, 1.0 / n);
        PoolOverCounts(mine, entry.mean);
        cell.clips = std::max(cell.clips, n);
        cell.methods.push_back(entry);
      }
      if (cell.clips == 0) continue;
      const auto baseline = std::find_if(cell.methods.begin(), cell.methods.end(),
                                         [](const FoldMethodMean& m) { return m.method == kBaselineMethod; });
      if (baseline != cell.methods.end() && baseline->mean.mpjpe_unkeyed_cm > 0.0)
        for (FoldMethodMean& m : cell.methods)
          m.below_mean_pct = 100.0 * (baseline->mean.mpjpe_unkeyed_cm - m.mean.mpjpe_unkeyed_cm) /
                             baseline->mean.mpjpe_unkeyed_cm;
      cells.push_back(cell);
    }
  return cells;
}

std::vector<AboveMeanCount> CountAboveMean(const std::vector<FoldCell>& cells) {
  std::vector<AboveMeanCount> counts;
  for (const FoldCell& cell : cells) {
    const auto baseline = std::find_if(cell.methods.begin(), cell.methods.end(),
                                       [](const FoldMethodMean& m) { return m.method == kBaselineMethod; });
    if (baseline == cell.methods.end()) continue;
    for (const FoldMethodMean& m : cell.methods) {
      if (m.method == kBaselineMethod) continue;
      auto it = std::find_if(counts.begin(), counts.end(), [&](const AboveMeanCount& c) {
        return c.half == cell.half && c.method == m.method;
      });
      if (it == counts.end()) it = counts.insert(counts.end(), AboveMeanCount{cell.half, m.method, 0, 0});
      ++it->cells;
      if (m.mean.mpjpe_unkeyed_cm > baseline->mean.mpjpe_unkeyed_cm) ++it->above;
    }
  }
  return counts;
}

}  // namespace mocapfill
