#include "tests/processing/held_out_fill.h"

#include <gtest/gtest.h>

#include <cstdio>

#include "formats/motion_io.h"
#include "processing/evaluation/scenarios.h"
#include "processing/evaluation/sketch_maker.h"
#include "tests/support/default_db.h"
#include "tests/support/test_paths.h"

namespace mocapfill::testing {

Result<std::vector<std::vector<FillMetrics>>> FillHeldOutTakes(FillEngine& engine, const MotionDatabase& db,
                                                               const std::string& scenario,
                                                               const std::vector<std::string>& takes,
                                                               const std::vector<FillOptions>& variants) {
  ASSIGN_OR_RETURN(const SketchScenario found, FindSketchScenario(scenario));
  std::vector<std::vector<FillMetrics>> metrics;
  for (const std::string& take : takes) {
    ASSIGN_OR_RETURN(const Scene truth, ImportFile(DataPath("bandai-namco-1/data/dataset-1_" + take + ".bvh")));
    ASSIGN_OR_RETURN(const MotionClip sketch, MakeSketch(db.skeleton(), truth.clips[0], found.sketch));
    metrics.emplace_back();
    for (const FillOptions& options : variants) {
      ASSIGN_OR_RETURN(const FillResult filled, engine.Fill(sketch, options));
      ASSIGN_OR_RETURN(const FillMetrics m, ScoreFill(db.skeleton(), truth.clips[0], sketch, filled.clip, db.root_joint()));
      metrics.back().push_back(m);
    }
  }
  return metrics;
}

Result<ProudSums> FillProudTakesByCategory(FillEngine& engine, const MotionDatabase& db,
                                           const std::vector<FillOptions>& variants) {
  const std::vector<std::string> locomotion = {"walk_proud_001", "run_proud_001", "walk-left_proud_001"};
  const std::vector<std::string> gestures = {"bow_proud_001", "bye_proud_001", "byebye_proud_001", "guide_proud_001"};
  std::vector<std::string> takes = locomotion;
  takes.insert(takes.end(), gestures.begin(), gestures.end());
  ASSIGN_OR_RETURN(const std::vector<std::vector<FillMetrics>> m, FillHeldOutTakes(engine, db, "legs8", takes, variants));
  ProudSums sums{std::vector<double>(variants.size(), 0.0), std::vector<double>(variants.size(), 0.0), 0.0};
  for (size_t t = 0; t < takes.size(); ++t)
    for (size_t v = 0; v < variants.size(); ++v) {
      (t < locomotion.size() ? sums.locomotion : sums.gestures)[v] += m[t][v].mpjpe_unkeyed_cm;
      sums.key_error_max_deg = std::max(sums.key_error_max_deg, m[t][v].key_error_max_deg);
    }
  return sums;
}

VariantScores ScoreVariants(const std::vector<std::vector<FillMetrics>>& metrics) {
  const size_t variants = metrics.empty() ? 0 : metrics[0].size();
  VariantScores scores{std::vector<double>(variants, 0.0), std::vector<double>(variants, 0.0), 0.0};
  std::vector<double> contacts(variants, 0.0);
  for (const std::vector<FillMetrics>& take : metrics)
    for (size_t v = 0; v < variants; ++v) {
      scores.mpjpe_cm[v] += take[v].mpjpe_unkeyed_cm / metrics.size();
      scores.skate_cm_per_s[v] += take[v].foot_skate_cm_per_s * take[v].foot_contact_frames;
      contacts[v] += take[v].foot_contact_frames;
      scores.key_error_max_deg = std::max(scores.key_error_max_deg, take[v].key_error_max_deg);
    }
  for (size_t v = 0; v < variants; ++v) scores.skate_cm_per_s[v] /= std::max(1.0, contacts[v]);
  return scores;
}

std::optional<VariantScores> ScoreBeforeAndNow(const std::string& style, const std::string& scenario,
                                               const std::vector<std::string>& takes, const FillOptions& before) {
  const MotionDatabase& db = BandaiDbWithout(style);
  FillEngine engine(db);
  Result<std::vector<std::vector<FillMetrics>>> m =
      FillHeldOutTakes(engine, db, scenario, takes, {before, FillOptions{}});
  if (!m.ok()) {
    ADD_FAILURE() << m.status().message();
    return std::nullopt;
  }
  const VariantScores scores = ScoreVariants(*m);
  EXPECT_LT(scores.key_error_max_deg, 0.01);
  std::printf("%s scenario, %s locomotion: before %.3f cm, feet %.2f cm/s on the capture's contacts; now %.3f cm, "
              "%.2f cm/s\n",
              scenario.c_str(), style.c_str(), scores.mpjpe_cm[0], scores.skate_cm_per_s[0], scores.mpjpe_cm[1],
              scores.skate_cm_per_s[1]);
  return scores;
}

}  // namespace mocapfill::testing
