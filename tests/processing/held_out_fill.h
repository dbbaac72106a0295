// Takes of a style the database lacks, filled and scored as `mocapfill eval` does for one
// leave-one-style-out fold: the suites that measure what an option buys on held-out takes share it.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/core/status.h"
#include "processing/evaluation/metrics.h"
#include "processing/fill/fill_engine.h"

namespace mocapfill::testing {

// Each take (a Bandai-Namco corpus name without its "dataset-1_" prefix, as
// "walk_proud_001") imported from the shared corpus, sketched as the named scenario
// (scenarios.h: "legs8", "root", ...) on `engine`'s database rig, filled under each of
// `variants` and scored against the capture: metrics[take][variant].
Result<std::vector<std::vector<FillMetrics>>> FillHeldOutTakes(FillEngine& engine, const MotionDatabase& db,
                                                               const std::string& scenario,
                                                               const std::vector<std::string>& takes,
                                                               const std::vector<FillOptions>& variants);

// Three locomotion takes (walk, run, walk-left) and four gestures (bow, bye, byebye, guide) of
// the proud style, sketched as legs8 on a database without it (BandaiDbWithout("proud")),
// filled under each variant: the unkeyed MPJPE summed over each category, per variant (cm),
// and the largest key error over all fills (degrees).
struct ProudSums {
  std::vector<double> locomotion, gestures;
  double key_error_max_deg = 0.0;
};
Result<ProudSums> FillProudTakesByCategory(FillEngine& engine, const MotionDatabase& db,
                                           const std::vector<FillOptions>& variants);

// Per variant, over the takes of FillHeldOutTakes' metrics[take][variant]: the unkeyed MPJPE
// averaged over the takes (cm), the feet's skating pooled over the capture's contact frames
// (cm/s), and the largest key error over every fill (degrees).
struct VariantScores {
  std::vector<double> mpjpe_cm, skate_cm_per_s;
  double key_error_max_deg = 0.0;
};
VariantScores ScoreVariants(const std::vector<std::vector<FillMetrics>>& metrics);

// Fills `takes` of the held-out `style` as `scenario` sketches against the other styles
// (BandaiDbWithout), with `before` and with the default options (variants 0 and 1); checks
// the keys (a test failure otherwise), prints both and returns their scores, or nothing when
// a fill fails (the failure recorded).
std::optional<VariantScores> ScoreBeforeAndNow(const std::string& style, const std::string& scenario,
                                               const std::vector<std::string>& takes, const FillOptions& before);

}  // namespace mocapfill::testing
