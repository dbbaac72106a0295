// The report of a fill by any method: the fragment methods' report (sources, seams, coverage,
// joints, stage times) plus where the PCA-based methods' model came from and the Ceres summary
// of the hybrid's key fit.
#pragma once

#include <string>

#include "processing/pca/ceres_fit/pca_fit.h"
#include "processing/synthesis/fragment_fill_report.h"

namespace mocapfill {

struct FillReport : FragmentFillReport {
  // PCA methods: where the model came from ("given" or "built from the database"), its size,
  // and (hybrid) the Ceres summary of the key fit.
  std::string pca_model_source;
  int pca_components = 0;
  bool has_solver = false;
  SolverReport solver;
};

}  // namespace mocapfill
