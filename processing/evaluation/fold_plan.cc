#include "processing/evaluation/fold_plan.h"

#include <algorithm>
#include <set>

namespace mocapfill {

namespace {

std::string FoldValueOf(const ClipLabels& labels, const std::string& key) {
  const auto it = labels.find(key);
  return it == labels.end() ? "" : it->second;
}

bool Listed(const std::vector<std::string>& list, const std::string& value) {
  return std::find(list.begin(), list.end(), value) != list.end();
}

}  // namespace

Result<Split> ParseSplit(const std::string& name) {
  for (Split s : {Split::kNone, Split::kTuning, Split::kReporting, Split::kBoth})
    if (name == SplitName(s)) return s;
  return InvalidArgument("--split: unknown value '" + name + "' (allowed: none, tuning, reporting, both)");
}

const char* SplitName(Split split) {
  switch (split) {
    case Split::kNone: return "none";
    case Split::kTuning: return "tuning";
    case Split::kReporting: return "reporting";
    case Split::kBoth: return "both";
  }
  return "none";
}

SplitHalves SplitFoldValues(const std::vector<std::string>& values) {
  const std::set<std::string> sorted(values.begin(), values.end());
  SplitHalves halves;
  bool tuning = true;
  for (const std::string& v : sorted) {
    (tuning ? halves.tuning : halves.reporting).push_back(v);
    tuning = !tuning;
  }
  return halves;
}

Result<std::vector<PlannedFold>> PlanFolds(const std::vector<ClipLabels>& labels, const FoldPlanOptions& options) {
  std::vector<std::string> values(labels.size());
  for (size_t i = 0; i < labels.size(); ++i) {
    values[i] = FoldValueOf(labels[i], options.fold_label);
    if (values[i].empty())
      return InvalidData("clip " + std::to_string(i) + " has no '" + options.fold_label + "' label");
  }
  const SplitHalves halves = SplitFoldValues(values);
  // (half, the folds it tests, the folds its databases may draw from)
  struct HalfPlan {
    const char* half;
    std::vector<std::string> tested, pool;
  };
  std::vector<HalfPlan> plans;
  const std::set<std::string> distinct(values.begin(), values.end());
  const std::vector<std::string> every(distinct.begin(), distinct.end());
  if (options.split == Split::kNone) plans.push_back({kNoHalf, every, every});
  if (options.split == Split::kTuning || options.split == Split::kBoth)
    plans.push_back({kTuningHalf, halves.tuning, halves.tuning});
  if (options.split == Split::kReporting || options.split == Split::kBoth)
    plans.push_back({kReportingHalf, halves.reporting, every});
  std::vector<PlannedFold> folds;
  for (const HalfPlan& plan : plans)
    for (const std::string& fold : plan.tested) {
      if (!options.only_folds.empty() && !Listed(options.only_folds, fold)) continue;
      PlannedFold planned{plan.half, fold, {}, {}};
      for (size_t i = 0; i < values.size(); ++i) {
        if (values[i] == fold) planned.tests.push_back(static_cast<int>(i));
        else if (Listed(plan.pool, values[i])) planned.database.push_back(static_cast<int>(i));
      }
      if (planned.database.empty())
        return InvalidArgument(std::string("fold '") + fold + "' of the " + plan.half +
                               " half has no other fold to build its database from (the half needs at least two " +
                               options.fold_label + " values)");
      folds.push_back(std::move(planned));
    }
  if (folds.empty()) return InvalidArgument("no clip belongs to the requested folds");
  return folds;
}

}  // namespace mocapfill
