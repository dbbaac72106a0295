// What `mocapfill eval` prints: the table (per half: means with 95 % bootstrap intervals, the
// relative difference to `mean`, the count of fold cells above `mean`; optionally per fold)
// and the JSON carrying the same and every clip's scores.
#pragma once

#include <string>
#include <vector>

#include "processing/evaluation/loso.h"

namespace mocapfill::cli {

struct EvalReportContext {
  std::string loso;                  // fold label; unused with `against`
  std::vector<std::string> against;  // fixed database paths (empty: leave-one-out)
  std::string scenario;              // empty: keep and every
  std::string keep;
  int every = 0;
  Split split = Split::kNone;
  BootstrapOptions bootstrap;
  std::string default_method;  // the fill's default, compared with `mean` per fold
  bool by_fold = false;        // the table lists every fold cell
};

void PrintEvalTable(const EvaluationResult& r, const EvalReportContext& context);
void PrintEvalJson(const EvaluationResult& r, const EvalReportContext& context);

}  // namespace mocapfill::cli
