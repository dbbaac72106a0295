// The split-half evaluation protocol: bootstrap intervals, the two halves of the fold values,
// the fold plan (which clips each fold's database may hold) and the ground-penetration metric,
// on the shipped default database and, where named Corpus, on the shared Bandai-Namco set.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <set>

#include "formats/mfdb/motion_folder.h"
#include "formats/motion_io.h"
#include "processing/core/kinematics.h"
#include "processing/evaluation/bootstrap.h"
#include "processing/evaluation/fold_plan.h"
#include "processing/evaluation/metrics.h"
#include "processing/evaluation/scenarios.h"
#include "processing/evaluation/sketch_maker.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

Scene LoadFixtureWalk() {
  Result<Scene> scene = ImportFile(testing::FixturePath("default_db/dataset-1_walk_happy_001.bvh"));
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  return scene.ok() ? std::move(*scene) : Scene{};
}

// Real values to resample: the hips' height (cm) on every frame of a captured walk.
std::vector<double> HipHeights() {
  const Scene walk = LoadFixtureWalk();
  std::vector<double> out;
  if (walk.clips.empty()) return out;
  const int hips = *walk.skeleton.Find("Hips");
  const std::vector<Eigen::Vector3d> world = ComputeWorldPositions(walk.skeleton, walk.clips[0]);
  for (int f = 0; f < walk.clips[0].num_frames; ++f) out.push_back(100.0 * world[f * walk.clips[0].num_joints + hips].y());
  return out;
}

double SampleMean(const std::vector<double>& v) {
  double sum = 0.0;
  for (double x : v) sum += x;
  return sum / v.size();
}

std::vector<ClipLabels> LabelsOf(const std::string& folder) {
  std::vector<ClipLabels> labels;
  Result<std::vector<std::string>> files = ListMotionFiles({folder});
  EXPECT_TRUE(files.ok()) << files.status().message();
  if (!files.ok()) return labels;
  for (const std::string& f : *files) {
    Result<ClipLabels> l = ReadClipLabels(f);
    EXPECT_TRUE(l.ok()) << l.status().message();
    if (l.ok()) labels.push_back(*l);
  }
  return labels;
}

std::vector<std::string> StyleValues(const std::vector<ClipLabels>& labels) {
  std::vector<std::string> out;
  for (const ClipLabels& l : labels) out.push_back(l.at("style"));
  return out;
}

TEST(Bootstrap, IntervalContainsTheSampleMean) {
  const std::vector<double> heights = HipHeights();
  ASSERT_GT(heights.size(), 100u);
  const Interval i = BootstrapMean(heights);
  EXPECT_LT(i.lo, SampleMean(heights));
  EXPECT_GT(i.hi, SampleMean(heights));
  EXPECT_GT(i.hi - i.lo, 0.01);  // a walk's hips bob by centimetres
}

// Equal weights give the plain mean's interval; weights that favour the high values move the
// interval up, and it contains the weighted mean.
TEST(Bootstrap, WeightedMeanIntervalFollowsItsWeights) {
  const std::vector<double> heights = HipHeights();
  ASSERT_GT(heights.size(), 100u);
  const Interval plain = BootstrapMean(heights);
  const Interval even = BootstrapWeightedMean(heights, std::vector<double>(heights.size(), 3.0));
  EXPECT_NEAR(even.lo, plain.lo, 1e-12);
  EXPECT_NEAR(even.hi, plain.hi, 1e-12);
  const double middle = SampleMean(heights);
  std::vector<double> weights;
  double sum = 0.0, total = 0.0;
  for (double h : heights) {
    weights.push_back(h > middle ? 4.0 : 1.0);
    sum += weights.back() * h;
    total += weights.back();
  }
  const Interval high = BootstrapWeightedMean(heights, weights);
  EXPECT_GT(high.lo, plain.lo);
  EXPECT_LT(high.lo, sum / total);
  EXPECT_GT(high.hi, sum / total);
}

TEST(Bootstrap, SameSeedSameIntervalOtherSeedOther) {
  const std::vector<double> heights = HipHeights();
  ASSERT_FALSE(heights.empty());
  const Interval a = BootstrapMean(heights), b = BootstrapMean(heights);
  EXPECT_EQ(a.lo, b.lo);
  EXPECT_EQ(a.hi, b.hi);
  BootstrapOptions other;
  other.seed = 16;
  const Interval c = BootstrapMean(heights, other);
  EXPECT_TRUE(c.lo != a.lo || c.hi != a.hi);
}

// Four copies of every value: the mean's spread shrinks by about sqrt(4).
TEST(Bootstrap, LargerSampleOfTheSameValuesIsNarrower) {
  const std::vector<double> heights = HipHeights();
  std::vector<double> four;
  for (int k = 0; k < 4; ++k) four.insert(four.end(), heights.begin(), heights.end());
  const Interval small = BootstrapMean(heights), large = BootstrapMean(four);
  EXPECT_LT(large.hi - large.lo, 0.65 * (small.hi - small.lo));
  EXPECT_GT(large.hi - large.lo, 0.35 * (small.hi - small.lo));
}

TEST(Bootstrap, ConstantDataHasAnEmptyInterval) {
  const std::vector<double> heights = HipHeights();
  ASSERT_FALSE(heights.empty());
  const std::vector<double> constant(heights.size(), heights[0]);
  const Interval i = BootstrapMean(constant);
  EXPECT_EQ(i.lo, i.hi);
  EXPECT_NEAR(i.lo, heights[0], 1e-9);
}

// Paired by clip: values 10 % below their reference in every pair are 10 % below in every
// resample; unpaired noise widens the interval around the point estimate.
TEST(Bootstrap, PercentBelowIsPairedByIndex) {
  const std::vector<double> heights = HipHeights();
  ASSERT_FALSE(heights.empty());
  std::vector<double> lower;
  for (double h : heights) lower.push_back(0.9 * h);
  const RelativeDifference exact = BootstrapPercentBelow(lower, heights);
  EXPECT_NEAR(exact.percent, 10.0, 1e-9);
  EXPECT_NEAR(exact.interval.lo, 10.0, 1e-9);
  EXPECT_NEAR(exact.interval.hi, 10.0, 1e-9);
  std::vector<double> shifted(heights.begin() + 1, heights.end());
  shifted.push_back(heights[0]);  // the same values, paired with other frames
  const RelativeDifference noisy = BootstrapPercentBelow(shifted, heights);
  EXPECT_LE(noisy.interval.lo, noisy.percent);
  EXPECT_GE(noisy.interval.hi, noisy.percent);
  EXPECT_GT(noisy.interval.hi - noisy.interval.lo, 1e-6);
}

// Consecutive frames of a walk are alike, as the clips of one style are: resampling blocks of
// 5 frames (then frames within them) gives a wider interval than resampling frames, which
// treats them as independent. One group per item is the plain bootstrap, draw for draw.
TEST(Bootstrap, GroupsOfAlikeItemsWidenTheInterval) {
  const std::vector<double> heights = HipHeights();
  ASSERT_GT(heights.size(), 200u);
  BootstrapGroups blocks, singles;
  for (size_t i = 0; i < heights.size(); ++i) {
    blocks.push_back(static_cast<int>(i / 5));
    singles.push_back(static_cast<int>(i));
  }
  const Interval plain = BootstrapMean(heights);
  const Interval single = BootstrapMean(heights, {}, singles);
  EXPECT_EQ(single.lo, plain.lo);
  EXPECT_EQ(single.hi, plain.hi);
  const Interval grouped = BootstrapMean(heights, {}, blocks);
  EXPECT_LT(grouped.lo, SampleMean(heights));
  EXPECT_GT(grouped.hi, SampleMean(heights));
  EXPECT_GT(grouped.hi - grouped.lo, 1.5 * (plain.hi - plain.lo));
  std::vector<double> lower;
  for (double h : heights) lower.push_back(0.9 * h);
  const RelativeDifference exact = BootstrapPercentBelow(lower, heights, {}, blocks);
  EXPECT_NEAR(exact.interval.lo, 10.0, 1e-9);
  EXPECT_NEAR(exact.interval.hi, 10.0, 1e-9);
}

TEST(FoldPlan, HalvesAreSortedAlternatedAndIndependentOfOrder) {
  const SplitHalves h = SplitFoldValues({"tired", "happy", "normal", "happy", "angry"});
  EXPECT_EQ(h.tuning, (std::vector<std::string>{"angry", "normal"}));
  EXPECT_EQ(h.reporting, (std::vector<std::string>{"happy", "tired"}));
  const SplitHalves again = SplitFoldValues({"normal", "angry", "happy", "tired"});
  EXPECT_EQ(again.tuning, h.tuning);
  EXPECT_EQ(again.reporting, h.reporting);
}

TEST(FoldPlan, ParseSplitNamesTheAllowedValues) {
  EXPECT_EQ(*ParseSplit("both"), Split::kBoth);
  EXPECT_EQ(*ParseSplit("none"), Split::kNone);
  const Result<Split> bad = ParseSplit("half");
  ASSERT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().code(), ErrorCode::kInvalidArgument);
  EXPECT_NE(bad.status().message().find("--split"), std::string::npos);
  EXPECT_NE(bad.status().message().find("none, tuning, reporting, both"), std::string::npos);
}

// Checks a plan of `split` over `labels`: every fold tests exactly its own clips; a tuning
// fold's database holds tuning clips of other folds only; a reporting (or unsplit) fold's
// database holds every clip of every other fold.
void ExpectPlanHonest(const std::vector<ClipLabels>& labels, Split split) {
  const std::vector<std::string> styles = StyleValues(labels);
  const SplitHalves halves = SplitFoldValues(styles);
  Result<std::vector<PlannedFold>> plan = PlanFolds(labels, {"style", split, {}});
  ASSERT_TRUE(plan.ok()) << plan.status().message();
  std::set<std::string> tested;
  for (const PlannedFold& fold : *plan) {
    EXPECT_TRUE(tested.insert(fold.fold).second) << fold.fold << " planned twice";
    for (int i : fold.tests) EXPECT_EQ(styles[i], fold.fold);
    const bool tuning = fold.half == kTuningHalf;
    int expected_db = 0;
    for (size_t i = 0; i < styles.size(); ++i) {
      const bool in_tuning = std::count(halves.tuning.begin(), halves.tuning.end(), styles[i]) > 0;
      if (styles[i] != fold.fold && (!tuning || in_tuning)) ++expected_db;
      if (styles[i] == fold.fold) {
        EXPECT_TRUE(std::count(fold.tests.begin(), fold.tests.end(), int(i))) << fold.fold << " misses clip " << i;
      }
    }
    EXPECT_EQ(static_cast<int>(fold.database.size()), expected_db) << fold.fold;
    for (int i : fold.database) {
      EXPECT_NE(styles[i], fold.fold) << "fold " << fold.fold << " holds its own clip " << i;
      if (tuning) {
        EXPECT_EQ(std::count(halves.reporting.begin(), halves.reporting.end(), styles[i]), 0)
            << "tuning fold " << fold.fold << " holds the reporting clip " << labels[i].at("name");
      }
    }
  }
  std::set<std::string> expected;
  if (split != Split::kReporting) expected.insert(halves.tuning.begin(), halves.tuning.end());
  if (split != Split::kTuning) expected.insert(halves.reporting.begin(), halves.reporting.end());
  EXPECT_EQ(tested, expected);
}

TEST(FoldPlan, DefaultDatabaseFoldsNeverLetReportingClipsIntoTuning) {
  const std::vector<ClipLabels> labels = LabelsOf(testing::FixturePath("default_db"));
  ASSERT_EQ(labels.size(), 21u);
  const SplitHalves halves = SplitFoldValues(StyleValues(labels));
  EXPECT_EQ(halves.tuning, (std::vector<std::string>{"happy", "tired"}));
  EXPECT_EQ(halves.reporting, (std::vector<std::string>{"normal"}));
  for (Split split : {Split::kNone, Split::kTuning, Split::kReporting, Split::kBoth}) ExpectPlanHonest(labels, split);
  Result<std::vector<PlannedFold>> both = PlanFolds(labels, {"style", Split::kBoth, {}});
  ASSERT_TRUE(both.ok());
  ASSERT_EQ(both->size(), 3u);  // tuning folds first, each half in sorted order
  EXPECT_EQ((*both)[0].fold, "happy");
  EXPECT_EQ((*both)[0].half, kTuningHalf);
  EXPECT_EQ((*both)[0].database.size(), 7u);  // tired's clips only
  EXPECT_EQ((*both)[2].fold, "normal");
  EXPECT_EQ((*both)[2].half, kReportingHalf);
  EXPECT_EQ((*both)[2].database.size(), 14u);
}

TEST(FoldPlan, ATuningHalfOfOneValueIsRefused) {
  std::vector<ClipLabels> labels = LabelsOf(testing::FixturePath("default_db"));
  labels.erase(std::remove_if(labels.begin(), labels.end(), [](const ClipLabels& l) { return l.at("style") == "tired"; }),
               labels.end());
  const Result<std::vector<PlannedFold>> plan = PlanFolds(labels, {"style", Split::kTuning, {}});
  ASSERT_FALSE(plan.ok());
  EXPECT_NE(plan.status().message().find("tuning half"), std::string::npos) << plan.status().message();
  EXPECT_TRUE(PlanFolds(labels, {"style", Split::kNone, {}}).ok());
}

TEST(FoldPlan, CorpusHalvesAreDisjointCompleteAndFixed) {
  MOCAPFILL_REQUIRE_CORPUS();
  const std::vector<ClipLabels> labels = LabelsOf(testing::DataPath("bandai-namco-1/data"));
  ASSERT_EQ(labels.size(), 174u);
  std::vector<std::string> styles = StyleValues(labels);
  const SplitHalves halves = SplitFoldValues(styles);
  EXPECT_EQ(halves.tuning.size(), 8u);
  EXPECT_EQ(halves.reporting.size(), 7u);
  std::set<std::string> all(styles.begin(), styles.end()), joined(halves.tuning.begin(), halves.tuning.end());
  for (const std::string& s : halves.reporting) EXPECT_TRUE(joined.insert(s).second) << s << " is in both halves";
  EXPECT_EQ(joined, all);
  std::reverse(styles.begin(), styles.end());
  EXPECT_EQ(SplitFoldValues(styles).tuning, halves.tuning);
  EXPECT_EQ(SplitFoldValues(styles).reporting, halves.reporting);
  for (Split split : {Split::kNone, Split::kBoth}) ExpectPlanHonest(labels, split);
}

// The fixture walk with its hips and legs keyed every 8 frames, against which motions on its
// skeleton are scored.
struct ScoredWalk {
  Scene walk = LoadFixtureWalk();
  Result<MotionClip> sketch = Legs8Sketch(walk);

  static Result<MotionClip> Legs8Sketch(const Scene& walk) {
    if (walk.clips.empty()) return InvalidArgument("the fixture walk has no clip");
    ASSIGN_OR_RETURN(const SketchScenario legs8, FindSketchScenario("legs8"));
    return MakeSketch(walk.skeleton, walk.clips[0], legs8.sketch);
  }
  Result<FillMetrics> Score(const MotionClip& filled) const {
    return ScoreFill(walk.skeleton, walk.clips[0], *sketch, filled, *walk.skeleton.Find("Hips"));
  }
};

// Penetration: a fill equal to the truth never goes below the truth's floor; the same walk
// lowered by 3 cm has every foot joint 3 cm below its floor at its lowest frame.
TEST(FillMetrics, PenetrationIsZeroForTheTruthAndTheDepthOfALoweredWalk) {
  const ScoredWalk w;
  ASSERT_TRUE(w.sketch.ok()) << w.sketch.status().message();
  const MotionClip& truth = w.walk.clips[0];
  Result<FillMetrics> same = w.Score(truth);
  ASSERT_TRUE(same.ok());
  EXPECT_EQ(same->penetration_max_cm, 0.0);
  EXPECT_EQ(same->penetration_mean_cm, 0.0);
  MotionClip lowered = truth;
  const int root = 0;  // the top joint: its translation is its world position
  ASSERT_EQ(w.walk.skeleton.parent(root), kNoParent);
  for (int f = 0; f < lowered.num_frames; ++f) lowered.translation(f, root).y() -= 0.03;
  Result<FillMetrics> low = w.Score(lowered);
  ASSERT_TRUE(low.ok());
  EXPECT_NEAR(low->penetration_max_cm, 3.0, 1e-9);
  EXPECT_GT(low->penetration_mean_cm, 0.0);
  EXPECT_LT(low->penetration_mean_cm, 3.0);  // frames with the foot raised go less deep
  EXPECT_NEAR(low->mpjpe_unkeyed_cm, 0.0, 1e-9);  // relative to the hips nothing moved
}

// Foot peak: a fill equal to the capture moves its feet no faster than the capture does (ratio
// 1: the walk's feet swing faster than the 1 m/s floor); the same walk shifted 30 cm sideways
// halfway through has every foot cross 30 cm in one frame (9 m/s), far past the capture's peak.
TEST(FillMetrics, FootPeakRatioSeesAFootSnappingAcrossTheFloor) {
  const ScoredWalk w;
  ASSERT_TRUE(w.sketch.ok()) << w.sketch.status().message();
  const MotionClip& truth = w.walk.clips[0];
  Result<FillMetrics> same = w.Score(truth);
  ASSERT_TRUE(same.ok());
  EXPECT_NEAR(same->foot_peak_ratio, 1.0, 1e-9);
  MotionClip shifted = truth;
  const int root = 0;  // the top joint: its translation is its world position
  for (int f = truth.num_frames / 2; f < truth.num_frames; ++f) shifted.translation(f, root).x() += 0.3;
  Result<FillMetrics> jumped = w.Score(shifted);
  ASSERT_TRUE(jumped.ok());
  std::printf("foot peak ratio: %.3f as captured, %.3f with a 30 cm jump\n", same->foot_peak_ratio,
              jumped->foot_peak_ratio);
  EXPECT_GT(jumped->foot_peak_ratio, 1.5);
  EXPECT_NEAR(jumped->mpjpe_unkeyed_cm, 0.0, 1e-9);  // relative to the hips nothing moved
}

}  // namespace
}  // namespace mocapfill
