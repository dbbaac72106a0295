// Coverage of a sketch by the database: a walk the locomotion database holds is
// covered and left alone; motions it does not hold (the shipped walk with its thighs turned
// into poses no take has; a dance, a kick against the default database) are reported as poorly
// covered, named in a warning, and blended towards the mean pose, which scores no worse than
// the guess.
#include <gtest/gtest.h>

#include <cstdio>

#include "formats/motion_io.h"
#include "processing/core/rotation.h"
#include "processing/evaluation/metrics.h"
#include "processing/evaluation/sketch_maker.h"
#include "processing/fill/fill_engine.h"
#include "processing/sketch_fill/sketch_fill.h"
#include "processing/synthesis/coverage.h"
#include "tests/support/default_db.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::DefaultDb;

const std::vector<std::string> kLegs = {"Hips",       "UpperLeg_L", "LowerLeg_L", "Foot_L", "Toes_L",
                                        "UpperLeg_R", "LowerLeg_R", "Foot_R",     "Toes_R"};

bool HasCoverageWarning(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings)
    if (w.rfind("coverage:", 0) == 0) return true;
  return false;
}

int PoorFrames(const CoverageReport& c) {
  int frames = 0;
  for (const PoorlyCoveredStretch& p : c.poor) frames += p.last_frame - p.first_frame + 1;
  return frames;
}

// The shipped walk with both thighs turned 100 degrees about their bone's local Z on every
// frame and key: legs raised sideways through a whole walk, which no database take holds.
MotionClip WalkWithRaisedThighs() {
  MotionClip sketch = testing::ShippedSketchOnDefaultDbRig();
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(100.0 / kDegPerRad, Eigen::Vector3d::UnitZ()));
  for (const char* name : {"UpperLeg_L", "UpperLeg_R"}) {
    const int j = *DefaultDb().skeleton().Find(name);
    for (int f = 0; f < sketch.num_frames; ++f) sketch.rotation(f, j) = sketch.rotation(f, j) * turn;
    for (Eigen::Quaterniond& q : sketch.keys[j].rotation_values) q = q * turn;
  }
  return sketch;
}

TEST(Coverage, StretchesAndPriorWeightsFollowTheUnexplainedShare) {
  const std::vector<SketchFragment> fragments = {{0, 9, true}, {9, 19, false}, {19, 29, true}, {29, 39, false}};
  // Nearest squared distances against energies: shares 0.01, 0.06 (between the thresholds),
  // 0.20 (beyond none_share), 0.03 (between the texture thresholds only).
  const std::vector<std::vector<Candidate>> nearest = {{{0, 0.01f}}, {{1, 0.06f}}, {{2, 0.2f}}, {{3, 0.03f}}};
  const std::vector<float> energies = {1.0f, 1.0f, 1.0f, 1.0f};
  const CoverageOptions options;  // poor 0.04, none 0.08; texture 0.02, 0.04
  const CoverageReport c = MeasureCoverage(fragments, nearest, energies, 0.5, options);
  ASSERT_TRUE(c.measured);
  ASSERT_EQ(c.fragments.size(), 4u);
  EXPECT_NEAR(c.fragments[1].unexplained, 0.06, 1e-6);
  EXPECT_NEAR(c.fragments[1].takes_ratio, std::sqrt(0.06) / 0.5, 1e-6);
  EXPECT_NEAR(c.fragments[1].prior_weight, 0.5, 1e-6);  // halfway between the thresholds
  EXPECT_EQ(c.fragments[2].prior_weight, 1.0);
  EXPECT_EQ(c.fragments[0].prior_weight, 0.0);
  EXPECT_EQ(c.fragments[3].prior_weight, 0.0);
  EXPECT_EQ(c.fragments[0].texture_weight, 0.0);
  EXPECT_EQ(c.fragments[1].texture_weight, 1.0);
  EXPECT_NEAR(c.fragments[3].texture_weight, 0.5, 1e-6);
  ASSERT_EQ(c.poor.size(), 1u);  // fragments 1 and 2 form one stretch
  EXPECT_EQ(c.poor[0].first_frame, 9);
  EXPECT_EQ(c.poor[0].last_frame, 29);
  EXPECT_NEAR(c.poor[0].worst_unexplained, 0.2, 1e-6);
  // Per frame: linear between fragment middles, so no step at the seams.
  const Eigen::VectorXd w = WeightPerFrame(c, &FragmentCoverage::prior_weight, 40);
  EXPECT_EQ(w[0], 0.0);
  EXPECT_NEAR(w[14], 0.5, 1e-6);  // float distances
  EXPECT_NEAR(w[24], 1.0, 1e-6);
  for (int f = 1; f < 40; ++f) EXPECT_LE(std::abs(w[f] - w[f - 1]), 0.11) << f;

  CoverageOptions warn_only;
  warn_only.blend = false;
  const CoverageReport warned = MeasureCoverage(fragments, nearest, energies, 0.5, warn_only);
  EXPECT_EQ(warned.poor.size(), 1u);
  EXPECT_EQ(WeightPerFrame(warned, &FragmentCoverage::prior_weight, 40).maxCoeff(), 0.0);
  EXPECT_EQ(WeightPerFrame(warned, &FragmentCoverage::texture_weight, 40).maxCoeff(), 0.0);
  EXPECT_TRUE(warned.prior.empty());
}

TEST(Coverage, ThresholdsAreValidated) {
  FillOptions o;
  o.coverage.poor_share = 0.1;
  o.coverage.none_share = 0.05;
  const Status s = o.Validate();
  EXPECT_EQ(s.code(), ErrorCode::kInvalidArgument);
  EXPECT_NE(s.message().find("coverage.none_share"), std::string::npos) << s.message();
  o.coverage.poor_share = 0.0;
  EXPECT_NE(o.Validate().message().find("coverage.poor_share"), std::string::npos);
}

// The shipped walk against the locomotion database: every fragment covered, no synthesised
// joint blended (they equal the warn-only fill's), no warning.
TEST(Coverage, ShippedWalkIsCoveredAndLeftAlone) {
  Result<Scene> sketch = ImportFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  ASSERT_TRUE(sketch.ok());
  Result<SketchFillResult> r = FillSketch(*sketch, DefaultDb(), {});
  ASSERT_TRUE(r.ok()) << r.status().message();
  const CoverageReport& c = r->report.coverage;
  ASSERT_TRUE(c.measured);
  ASSERT_GE(c.fragments.size(), 10u);
  EXPECT_GT(c.reference_distance, 0.0);
  double worst = 0.0;
  for (const FragmentCoverage& f : c.fragments) worst = std::max(worst, f.unexplained);
  std::printf("shipped walk: %zu fragments, worst unexplained share %.4f\n", c.fragments.size(), worst);
  EXPECT_LT(worst, c.poor_share);
  EXPECT_TRUE(c.poor.empty());
  EXPECT_FALSE(HasCoverageWarning(r->warnings));

  FillEngine engine(DefaultDb());
  FillOptions blend, warn;
  warn.coverage.blend = false;
  const MotionClip walk = testing::ShippedSketchOnDefaultDbRig();
  Result<FillResult> a = engine.Fill(walk, blend), b = engine.Fill(walk, warn);
  ASSERT_TRUE(a.ok() && b.ok());
  for (int f = 0; f < walk.num_frames; ++f)
    for (int j = 0; j < walk.num_joints; ++j) {
      if (!walk.keys[j].empty()) continue;
      ASSERT_EQ(a->clip.rotation(f, j).coeffs(), b->clip.rotation(f, j).coeffs()) << f;
    }
}

// Thighs raised sideways through a walk: poorly covered; where the prior's weight is 1 the
// synthesised joints are the mean-pose fill's; the warning names the time range and the synthesised joints.
TEST(Coverage, RaisedThighsArePoorlyCoveredAndBlendedTowardsTheMeanPose) {
  const MotionClip sketch = WalkWithRaisedThighs();
  FillEngine engine(DefaultDb());
  FillOptions mean_options;
  mean_options.method = FillMethod::kMean;
  Result<FillResult> filled = engine.Fill(sketch, {});
  Result<FillResult> mean = engine.Fill(sketch, mean_options);
  ASSERT_TRUE(filled.ok() && mean.ok()) << filled.status().message();
  const CoverageReport& c = filled->report.coverage;
  ASSERT_FALSE(c.poor.empty());
  const int poor = PoorFrames(c);
  std::printf("raised thighs: %d of %d frames poorly covered, %zu stretches\n", poor, sketch.num_frames,
              c.poor.size());
  EXPECT_GT(poor, sketch.num_frames / 2);
  const Eigen::VectorXd w = WeightPerFrame(c, &FragmentCoverage::prior_weight, sketch.num_frames);
  int full = 0;
  double worst_deg = 0.0;
  for (int f = 0; f < sketch.num_frames; ++f) {
    if (w[f] < 1.0) continue;
    ++full;
    for (int j = 0; j < sketch.num_joints; ++j)
      if (sketch.keys[j].empty())  // keyed joints: the sketch between keys, interpolated in tangent space
        worst_deg = std::max(worst_deg, GeodesicAngle(filled->clip.rotation(f, j), mean->clip.rotation(f, j)) * kDegPerRad);
  }
  EXPECT_GT(full, 0);
  EXPECT_LT(worst_deg, 1e-6);

  Scene scene;
  scene.skeleton = DefaultDb().skeleton();
  scene.clips = {sketch};
  Result<SketchFillResult> r = FillSketch(scene, DefaultDb(), {});
  ASSERT_TRUE(r.ok()) << r.status().message();
  ASSERT_TRUE(HasCoverageWarning(r->warnings));
  std::string warning;
  for (const std::string& line : r->warnings)
    if (line.rfind("coverage:", 0) == 0) warning = line;
  std::printf("%s\n", warning.c_str());
  EXPECT_NE(warning.find(" s is poorly covered"), std::string::npos);
  EXPECT_NE(warning.find("Head"), std::string::npos);  // among the synthesised joints named
  EXPECT_NE(warning.find("towards the database mean pose"), std::string::npos);
}

// The largest third difference (m per frame cubed) of the root's path over frames [first, last].
double LargestRootJerk(const MotionClip& clip, int root, int first, int last) {
  double largest = 0.0;
  auto p = [&](int f) { return clip.translation(f, root); };
  for (int f = std::max(first, 2); f + 1 <= last; ++f)
    largest = std::max(largest, (p(f + 1) - 3.0 * p(f) + 3.0 * p(f - 1) - p(f - 2)).norm());
  return largest;
}

// Where the fill falls back to the sketch, the root still travels smoothly: its path, linear
// between the keys as the sketch has it, kinked at every key and jolted the whole body there
// (the jerkiest frames of poorly covered gestures). The keys stay exact.
TEST(Coverage, PoorlyCoveredTravelStaysSmoothThroughItsKeys) {
  const MotionClip sketch = WalkWithRaisedThighs();
  const int root = DefaultDb().root_joint();
  Result<FillResult> filled = FillEngine(DefaultDb()).Fill(sketch, {});
  ASSERT_TRUE(filled.ok()) << filled.status().message();
  const Eigen::VectorXd w =
      WeightPerFrame(filled->report.coverage, &FragmentCoverage::texture_weight, sketch.num_frames);
  ASSERT_GE(w.minCoeff(), 1.0);  // the texture has faded on every frame
  const int last = sketch.num_frames - 1;
  const double lerped = LargestRootJerk(sketch, root, 0, last), fill = LargestRootJerk(filled->clip, root, 0, last);
  std::printf("largest jerk of the root's path %.2f mm/frame^3, the sketch's %.2f\n", 1000.0 * fill, 1000.0 * lerped);
  EXPECT_LT(fill, 0.5 * lerped);
  double key_error = 0.0;
  for (int f : sketch.keys[root].translation_frames)
    key_error = std::max(key_error, (filled->clip.translation(f, root) - sketch.translation(f, root)).norm());
  EXPECT_LT(key_error, 1e-6);
}

// Upper-body error (cm) of the default method and of `mean` on a captured clip the default
// database does not hold, keyed at the root and legs every 8 frames.
struct Scores {
  double default_cm = 0.0, mean_cm = 0.0;
  int poor_frames = 0, frames = 0;
  bool warned = false;
};

Scores ScoreAgainstDefaultDb(const std::string& file) {
  Scores out;
  Result<Scene> truth = ImportFile(testing::DataPath("bandai-namco-1/data/" + file));
  EXPECT_TRUE(truth.ok());
  if (!truth.ok()) return out;
  SketchSpec spec;
  spec.keep_joints = kLegs;
  Result<MotionClip> sketch = MakeSketch(truth->skeleton, truth->clips[0], spec);
  EXPECT_TRUE(sketch.ok());
  if (!sketch.ok()) return out;
  FillEngine engine(DefaultDb());
  FillOptions mean_options;
  mean_options.method = FillMethod::kMean;
  Result<FillResult> filled = engine.Fill(*sketch, {});
  Result<FillResult> mean = engine.Fill(*sketch, mean_options);
  EXPECT_TRUE(filled.ok() && mean.ok());
  if (!filled.ok() || !mean.ok()) return out;
  const int root = DefaultDb().root_joint();
  out.default_cm = ScoreFill(truth->skeleton, truth->clips[0], *sketch, filled->clip, root)->mpjpe_unkeyed_cm;
  out.mean_cm = ScoreFill(truth->skeleton, truth->clips[0], *sketch, mean->clip, root)->mpjpe_unkeyed_cm;
  out.poor_frames = PoorFrames(filled->report.coverage);
  out.frames = sketch->num_frames;
  Scene scene = *truth;
  scene.clips = {*sketch};
  Result<SketchFillResult> r = FillSketch(scene, DefaultDb(), {});
  out.warned = r.ok() && HasCoverageWarning(r->warnings);
  std::printf("%s: default %.3f cm, mean %.3f cm, %d of %d frames poorly covered, warned %d\n", file.c_str(),
              out.default_cm, out.mean_cm, out.poor_frames, out.frames, out.warned);
  return out;
}

TEST(Coverage, DanceAgainstTheDefaultDatabaseWarnsAndIsNoWorseThanMean) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Scores s = ScoreAgainstDefaultDb("dataset-1_dance-short_normal_001.bvh");
  EXPECT_TRUE(s.warned);
  EXPECT_GT(s.poor_frames, s.frames / 2);
  EXPECT_LE(s.default_cm, s.mean_cm);
}

TEST(Coverage, CapturedWalkOfAnotherStyleIsCovered) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Scores s = ScoreAgainstDefaultDb("dataset-1_walk_proud_001.bvh");
  EXPECT_FALSE(s.warned);
  EXPECT_EQ(s.poor_frames, 0);
  EXPECT_LT(s.default_cm, 0.8 * s.mean_cm);
}

}  // namespace
}  // namespace mocapfill
