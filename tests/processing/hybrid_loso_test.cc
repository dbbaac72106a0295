// The leave-one-style-out protocol (the quality target of the hybrid method) over the shared
// Bandai-Namco corpus with the hierarchical and hybrid methods. The full protocol (174 clips)
// takes minutes on the 2-core machine (docs/fill.md has its table); this test runs the walks
// only (15 folds, one fold per held-out style, 30 clips), each fold's database and PCA model
// built from the other 14 styles, so no held-out style leaks into the model. About 60 s on
// the loaded 2-core machine.
#include <gtest/gtest.h>

#include <cstdio>

#include "formats/mfdb/motion_folder.h"
#include "processing/evaluation/loso.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

std::vector<LabeledClip> LoadCorpus() {
  std::vector<LabeledClip> clips;
  Result<std::vector<std::string>> files = ListMotionFiles({testing::DataPath("bandai-namco-1/data")});
  EXPECT_TRUE(files.ok()) << files.status().message();
  if (!files.ok()) return clips;
  Result<std::vector<LabeledScene>> scenes = ImportMotionFiles(*files, ImportOptions{}, 0);
  EXPECT_TRUE(scenes.ok()) << scenes.status().message();
  if (!scenes.ok()) return clips;
  for (LabeledScene& s : *scenes)
    for (MotionClip& clip : s.scene.clips) clips.push_back({s.scene.skeleton, std::move(clip), s.labels});
  return clips;
}

TEST(HybridLoso, HybridKeepsUpWithHierarchicalOnHeldOutWalkStyles) {
  MOCAPFILL_REQUIRE_CORPUS();
  const std::vector<LabeledClip> clips = LoadCorpus();
  ASSERT_GT(clips.size(), 100u);
  EvaluationOptions options;
  options.sketch.keep_joints = {"Hips", "UpperLeg_L", "LowerLeg_L", "Foot_L", "Toes_L",
                                "UpperLeg_R", "LowerLeg_R", "Foot_R", "Toes_R"};
  options.sketch.key_every_frames = 8;
  options.only_contents = {"walk"};
  for (FillMethod method : {FillMethod::kHierarchical, FillMethod::kHybrid}) {
    FillOptions fill;
    fill.method = method;
    options.methods.push_back({FillMethodName(method), fill});
  }
  Result<EvaluationResult> result = RunLeaveOneOut(clips, options);
  ASSERT_TRUE(result.ok()) << result.status().message();
  std::map<std::string, FillMetrics> all;
  for (const SummaryRow& row : result->summary)
    if (row.category == "all") {
      all[row.method] = row.mean;
      std::printf("%-12s %d clips: unkeyed %.3f cm, keyed between keys %.3f cm, NPSS %.4f, jitter %.3f, key %.4f deg\n",
                  row.method.c_str(), row.clips, row.mean.mpjpe_unkeyed_cm, row.mean.mpjpe_keyed_between_cm,
                  row.mean.npss, row.mean.jitter_ratio, row.mean.key_error_mean_deg);
    }
  EXPECT_EQ(result->folds, 15);
  // The hybrid's PCA fit starts from the hierarchical fill and must not lose what it holds:
  // measured 6.469 against 6.456 cm. (It was 0.2 % better before the hierarchical blend moved
  // towards its candidates' median posture, which the PCA fit pulls back a little.)
  EXPECT_LT(all["hybrid"].mpjpe_unkeyed_cm, 1.01 * all["hierarchical"].mpjpe_unkeyed_cm);
  // Walks alone sit above the 1.5 jitter bound for every fragment method (about 1.66 for
  // both); the [0.7, 1.5] target holds on the whole locomotion set (docs/fill.md). Here the
  // hybrid must not be jitterier than the hierarchical method it starts from.
  EXPECT_GT(all["hybrid"].jitter_ratio, 0.7);
  EXPECT_LT(all["hybrid"].jitter_ratio, 1.02 * all["hierarchical"].jitter_ratio);
  EXPECT_LT(all["hybrid"].key_error_mean_deg, 0.5);
}

}  // namespace
}  // namespace mocapfill
