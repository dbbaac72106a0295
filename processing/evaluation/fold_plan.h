// Which clips each fold of the evaluation tests and which it builds its database from. The
// split-half protocol keeps the clips that results are reported on out of every choice: the
// fold values (styles) are split in two fixed halves; the tuning half is evaluated
// leave-one-out inside itself (its folds' databases hold tuning clips only), the reporting
// half leave-one-out against every other fold of both halves. Defaults and weights are chosen
// on the tuning half's numbers, so the reporting half's stay an honest estimate.
#pragma once

#include <string>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/core/status.h"

namespace mocapfill {

enum class Split {
  kNone,       // plain leave-one-out over every fold, the database from every other fold
  kTuning,     // the tuning half only, inside itself
  kReporting,  // the reporting half only, against both halves
  kBoth,       // the tuning half, then the reporting half
};

// "none", "tuning", "reporting", "both"; kInvalidArgument naming the allowed values otherwise.
Result<Split> ParseSplit(const std::string& name);
const char* SplitName(Split split);

// The half names scores and summaries carry: "tuning", "reporting", and "all" without a split.
inline constexpr const char* kTuningHalf = "tuning";
inline constexpr const char* kReportingHalf = "reporting";
inline constexpr const char* kNoHalf = "all";

struct SplitHalves {
  std::vector<std::string> tuning;
  std::vector<std::string> reporting;
};

// The distinct values sorted by name and dealt alternately, the first to tuning: fixed by the
// values alone (not by clip order or counts), and balanced within one value.
SplitHalves SplitFoldValues(const std::vector<std::string>& values);

struct PlannedFold {
  std::string half;  // kTuningHalf, kReportingHalf or kNoHalf
  std::string fold;  // the held-out label value
  std::vector<int> tests;     // indices of the clips with that value, in input order
  std::vector<int> database;  // indices of the clips its database is built from, in input order
};

struct FoldPlanOptions {
  std::string fold_label = "style";
  Split split = Split::kNone;
  std::vector<std::string> only_folds;  // empty: every fold (the halves are formed before this filter)
};

// The folds to run, tuning folds before reporting folds, each half's in sorted order. Errors:
// a clip without the fold label (kInvalidData); no fold selected, or a tuning fold whose
// database would be empty (the tuning half needs two values) (kInvalidArgument).
Result<std::vector<PlannedFold>> PlanFolds(const std::vector<ClipLabels>& labels, const FoldPlanOptions& options);

}  // namespace mocapfill
