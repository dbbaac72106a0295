// Fill methods on real data: the embedded default database (fixtures/default_db, Bandai-Namco
// locomotion of three styles) and the shipped sketch of a walk in a style it does not hold.
#include <gtest/gtest.h>

#include <filesystem>

#include "formats/motion_io.h"
#include "processing/core/kinematics.h"
#include "processing/core/monotone_cubic.h"
#include "processing/core/rotation.h"
#include "processing/evaluation/metrics.h"
#include "processing/evaluation/scenarios.h"
#include "processing/evaluation/sketch_maker.h"
#include "processing/fill/fill_engine.h"
#include "processing/filtering/pyramid.h"
#include "processing/synthesis/fragment_matching.h"
#include "processing/synthesis/matching_database.h"
#include "processing/synthesis/hierarchical/hierarchy.h"
#include "processing/synthesis/sketch_signals.h"
#include "processing/texturing/activity_gain.h"
#include "processing/texturing/texture_channels.h"
#include "tests/processing/held_out_fill.h"
#include "tests/support/default_db.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

namespace fs = std::filesystem;

constexpr double kExactDeg = 1e-6;       // keys copied: only rounding
constexpr double kKeyToleranceDeg = 0.5;  // key fidelity after texturing

using testing::DefaultDb;

// The shipped glTF sketch in database joint order.
MotionClip Sketch() { return testing::ShippedSketchOnDefaultDbRig(); }

double MaxKeyErrorDeg(const MotionClip& sketch, const MotionClip& out) {
  double worst = 0.0;
  for (int j = 0; j < sketch.num_joints; ++j)
    for (int f : sketch.keys[j].rotation_frames)
      worst = std::max(worst, GeodesicAngle(sketch.rotation(f, j), out.rotation(f, j)) * kDegPerRad);
  return worst;
}

TEST(FillOptions, ValidateRejectsEveryOutOfRangeField) {
  EXPECT_TRUE(FillOptions{}.Validate().ok());
  FillOptions o;
  o.candidates = 0;
  EXPECT_EQ(o.Validate().code(), ErrorCode::kInvalidArgument);
  o = {};
  o.blend = o.candidates + 1;
  EXPECT_FALSE(o.Validate().ok());
  o = {};
  o.min_length_ratio = 1.5;
  EXPECT_FALSE(o.Validate().ok());
  o = {};
  o.crossfade = -1;
  EXPECT_FALSE(o.Validate().ok());
  o = {};
  o.synthesized_finest_band = -1;
  EXPECT_FALSE(o.Validate().ok());
  o = {};
  o.lead_detail = -0.1;
  EXPECT_FALSE(o.Validate().ok());
  o.lead_detail = 2.5;
  EXPECT_FALSE(o.Validate().ok());
  o = {};
  o.leg_sway_weight = -1.0;
  EXPECT_FALSE(o.Validate().ok());
  o = {};
  o.sway_speed_m_per_s = std::nan("");
  EXPECT_FALSE(o.Validate().ok());
  o = {};
  o.swing_gain = -0.1;
  EXPECT_FALSE(o.Validate().ok());
  o.swing_gain = 3.5;
  EXPECT_FALSE(o.Validate().ok());
  o = {};
  o.moving_travel_weight = -1.0;
  EXPECT_FALSE(o.Validate().ok());
  o = {};
  o.moving_speed_m_per_s = std::nan("");
  EXPECT_FALSE(o.Validate().ok());
  o = {};
  o.still_root_m_per_s = -0.01;
  EXPECT_FALSE(o.Validate().ok());
  o = {};
  o.texture_activity_window_s = std::nan("");
  EXPECT_FALSE(o.Validate().ok());
  o = {};
  o.leg_drivers = -1;
  EXPECT_FALSE(o.Validate().ok());
  EXPECT_EQ(*ParseFillMethod("nn"), FillMethod::kNearest);
  EXPECT_EQ(*ParseJoinCriterion("best-animation"), JoinCriterion::kBestAnimation);
  EXPECT_FALSE(ParseFillMethod("magic").ok());
}

// Fragments matched on a driver set of their own (the travel weighed otherwise where the root
// moves) find what matching them on that set alone finds: the same candidates, the same
// distances; the shared database gathering only rescales its columns.
TEST(FragmentMatching, EachFragmentMatchesOnItsOwnDriverSet) {
  const MotionDatabase& db = testing::DefaultDb();
  Result<SketchSignals> s = MakeSketchSignals(db, testing::ShippedSketchOnDefaultDbRig());
  ASSERT_TRUE(s.ok()) << s.status().message();
  const FragmentFillOptions options;
  const int band = BandForFrequency(options.fragment_band_hz, db.rate_hz(), 16);
  const int master = ChooseMasterChannel(*s, band, db.rate_hz());
  Result<std::vector<SketchFragment>> fragments = FragmentSketch(*s, master, band, db.rate_hz());
  ASSERT_TRUE(fragments.ok());
  ASSERT_GE(fragments->size(), 4u);
  Result<MatchingDatabase> mdb = MatchingDatabase::Build(db, *s, master, band, options);
  ASSERT_TRUE(mdb.ok()) << mdb.status().message();
  const Eigen::MatrixXd match = MatchingSignal(s->values, db.rate_hz(), options);
  std::vector<DrivenChannel> weighed;
  for (int c = 0; c < s->num_channels(); ++c)
    if (s->keyed[c]) weighed.push_back({c, c == db.RootFeatureChannel(kRootForward) ? 6.0 : 1.0});
  std::vector<DrivenChannel> plain = weighed;
  for (DrivenChannel& d : plain) d.weight = 1.0;
  std::vector<int> set_of(fragments->size());
  std::vector<SketchFragment> odd, even;
  for (size_t i = 0; i < fragments->size(); ++i) {
    set_of[i] = i % 2;
    (i % 2 ? odd : even).push_back((*fragments)[i]);
  }
  const auto by_set = MatchFragmentsBySet(*mdb, match, *fragments, {weighed, plain}, set_of, options);
  const auto alone_even = MatchFragments(*mdb, match, even, weighed, options);
  const auto alone_odd = MatchFragments(*mdb, match, odd, plain, options);
  ASSERT_EQ(by_set.size(), fragments->size());
  bool sets_differ = false;
  for (size_t i = 0; i < fragments->size(); ++i) {
    const std::vector<Candidate>& alone = i % 2 ? alone_odd[i / 2] : alone_even[i / 2];
    ASSERT_EQ(by_set[i].size(), alone.size());
    // Rounding may swap candidates whose distances tie, or one at the cut after the K best.
    std::map<int, float> found;
    for (const Candidate& c : alone) found[c.fragment] = c.distance;
    for (size_t k = 0; k < alone.size(); ++k) {
      const float tolerance = 1e-5f * (1.0f + alone[k].distance);
      EXPECT_NEAR(by_set[i][k].distance, alone[k].distance, tolerance) << "fragment " << i << ", candidate " << k;
      const auto same = found.find(by_set[i][k].fragment);
      EXPECT_NEAR(same == found.end() ? alone.back().distance : same->second, by_set[i][k].distance, tolerance);
    }
    if (i % 2) {
      const auto other = MatchFragments(*mdb, match, {(*fragments)[i]}, weighed, options);
      sets_differ = sets_differ || other[0].front().fragment != alone.front().fragment;
    }
  }
  EXPECT_TRUE(sets_differ);  // the two sets rank the database differently somewhere
}

TEST(SketchFilter, LerpsBetweenKeysAndHoldsOutside) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(10, 1);
  m(2, 0) = 1.0;
  m(6, 0) = 3.0;
  LerpBetweenKeys(m, {2, 6});
  EXPECT_DOUBLE_EQ(m(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(m(4, 0), 2.0);
  EXPECT_DOUBLE_EQ(m(9, 0), 3.0);
  EXPECT_EQ(PhaseKeys(10, 4, 1), (std::vector<int>{0, 1, 5, 9}));
  EXPECT_EQ(TextureBandCount(8, 30.0), 3);  // L0-L2 lie above 1.875 Hz
}

// A channel the sketch moves half as fast as the take lending it detail takes half its detail;
// one it moves as fast or faster, all of it; where both stand still, about all of it.
TEST(Texture, ActivityGainIsTheSketchsSpeedOverTheTakesAtMostOne) {
  const double rate = 30.0;
  Eigen::MatrixXd sketch(90, 3), source(90, 3);
  for (int t = 0; t < 90; ++t) {
    const double wave = std::sin(2.0 * M_PI * 1.0 * t / rate);  // 1 Hz, 0.5 rad amplitude below
    sketch.row(t) << 0.25 * wave, 0.5 * wave, 0.0;
    source.row(t) << 0.5 * wave, 0.25 * wave, 0.0;
  }
  const Eigen::MatrixXd gain = ActivityGain(sketch, source, rate, 1.0, 0.01);
  ASSERT_EQ(gain.rows(), 90);
  const double mean_speed = 0.5 * 2.0 * M_PI * 2.0 / M_PI;  // |d/dt| of 0.5 sin(2 pi t) averaged: 2 rad/s
  EXPECT_NEAR(gain(45, 0), (0.5 * mean_speed + 0.01) / (mean_speed + 0.01), 0.02);
  EXPECT_DOUBLE_EQ(gain(45, 1), 1.0);
  EXPECT_DOUBLE_EQ(gain(45, 2), 1.0);
  EXPECT_EQ(ActivityGain(sketch.topRows(1), source.topRows(1), rate, 1.0, 0.01), Eigen::MatrixXd::Ones(1, 3));
}

TEST(Hierarchy, GroupsBandaiUpperBodyIntoLimbChainsOutwardFromTheKeys) {
  const Skeleton& skeleton = DefaultDb().skeleton();
  std::vector<std::uint8_t> keyed(skeleton.num_joints(), 0);
  for (const char* name : {"joint_Root", "Hips", "UpperLeg_L", "LowerLeg_L", "Foot_L", "Toes_L", "UpperLeg_R",
                           "LowerLeg_R", "Foot_R", "Toes_R"})
    keyed[*skeleton.Find(name)] = 1;
  const std::vector<JointGroup> groups = PlanGroups(skeleton, keyed);
  ASSERT_EQ(groups.size(), 4u);
  EXPECT_EQ(groups[0].name, "Spine..Chest");
  EXPECT_EQ(groups[0].distance, 1);
  EXPECT_EQ(groups[1].name, "Neck..Head");
  EXPECT_EQ(groups[2].name, "Shoulder_L..Hand_L");
  EXPECT_EQ(groups[3].name, "Shoulder_R..Hand_R");
  EXPECT_EQ(groups[3].distance, 3);
}

TEST(Fill, RejectsASketchWithoutKeys) {
  MotionClip sketch = Sketch();
  for (JointKeys& k : sketch.keys) k = JointKeys{};
  FillEngine engine(DefaultDb());
  EXPECT_EQ(engine.Fill(sketch, FillOptions{}).status().code(), ErrorCode::kInvalidData);
}

TEST(Fill, EveryMethodKeepsTheKeysAndMovesTheUpperBody) {
  const MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  const int hand = *DefaultDb().skeleton().Find("Hand_R");
  for (FillMethod method : {FillMethod::kMean, FillMethod::kNearest, FillMethod::kFragment, FillMethod::kHierarchical}) {
    FillOptions options;
    options.method = method;
    options.texture = false;  // keyed joints copied exactly
    Result<FillResult> r = engine.Fill(sketch, options);
    ASSERT_TRUE(r.ok()) << r.status().message();
    EXPECT_LT(MaxKeyErrorDeg(sketch, r->clip), kExactDeg) << FillMethodName(method);
    double moved = 0.0;
    for (int f = 1; f < sketch.num_frames; ++f)
      moved = std::max(moved, GeodesicAngle(r->clip.rotation(f, hand), r->clip.rotation(0, hand)));
    if (method == FillMethod::kMean) {
      EXPECT_LT(moved, 1e-12);  // the mean pose does not move
    } else {
      EXPECT_GT(moved * kDegPerRad, 5.0) << FillMethodName(method);  // the arm swings
    }
  }
}

TEST(Fill, TexturingMovesKeyedJointsBetweenKeysAndRepinsTheKeys) {
  const MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  FillOptions options;
  options.texture = true;
  Result<FillResult> r = engine.Fill(sketch, options);
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_LT(r->report.key_error_mean_deg, kKeyToleranceDeg);
  EXPECT_LT(r->report.key_error_max_deg, 1e-3);  // re-pinned exactly up to rounding
  const int knee = *DefaultDb().skeleton().Find("LowerLeg_L");
  double moved = 0.0;
  for (int f = 0; f < sketch.num_frames; ++f)
    moved = std::max(moved, GeodesicAngle(sketch.rotation(f, knee), r->clip.rotation(f, knee)));
  EXPECT_GT(moved * kDegPerRad, 0.1);  // texture added between keys
}

TEST(Fill, IsDeterministic) {
  const MotionClip sketch = Sketch();
  FillEngine a(DefaultDb()), b(DefaultDb());
  FillOptions options;
  const FillResult ra = *a.Fill(sketch, options);
  options.threads = 1;  // the result must not depend on the thread count
  const FillResult rb = *b.Fill(sketch, options);
  for (size_t i = 0; i < ra.clip.rotations.size(); ++i)
    ASSERT_EQ(ra.clip.rotations[i].coeffs(), rb.clip.rotations[i].coeffs()) << i;
}

TEST(Fill, EveryJointKeyedEveryFrameIsLeftUnchangedWithoutTexture) {
  MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  FillOptions options;
  options.texture = false;
  options.method = FillMethod::kMean;
  const MotionClip dense = engine.Fill(sketch, options)->clip;  // any complete clip
  sketch = dense;
  sketch.KeyAllFrames();
  for (FillMethod method : {FillMethod::kFragment, FillMethod::kHierarchical}) {
    options.method = method;
    Result<FillResult> r = engine.Fill(sketch, options);
    ASSERT_TRUE(r.ok()) << r.status().message();
    for (size_t i = 0; i < sketch.rotations.size(); ++i) {
      ASSERT_EQ(r->clip.rotations[i].coeffs(), sketch.rotations[i].coeffs()) << i;
      ASSERT_EQ(r->clip.translations[i], sketch.translations[i]) << i;
    }
  }
}

// Mean third difference (m/s^3) of the root's translation.
double RootPathJerk(const MotionClip& clip, int root) {
  double sum = 0.0;
  for (int f = 2; f + 1 < clip.num_frames; ++f)
    sum += (clip.translation(f + 1, root) - 3.0 * clip.translation(f, root) + 3.0 * clip.translation(f - 1, root) -
            clip.translation(f - 2, root))
               .norm();
  const double rate = clip.sample_rate_hz;
  return clip.num_frames > 3 ? sum * rate * rate * rate / (clip.num_frames - 3) : 0.0;
}

// The keyed root's travel is textured like the keyed joints: the path passes through every
// translation key exactly, without the sketch's kink at each key (the shipped sketch is linear
// between keys); the whole path of an untextured fill stays the sketch's.
TEST(Fill, KeyedRootTravelMeetsItsKeysWithoutKinks) {
  const MotionClip sketch = Sketch();
  const int root = DefaultDb().root_joint();
  const std::vector<int>& keys = sketch.keys[root].translation_frames;
  ASSERT_GT(keys.size(), 10u);
  FillEngine engine(DefaultDb());
  Result<FillResult> r = engine.Fill(sketch, FillOptions{});
  ASSERT_TRUE(r.ok()) << r.status().message();
  double worst = 0.0;
  for (int f : keys) worst = std::max(worst, (r->clip.translation(f, root) - sketch.translation(f, root)).norm());
  EXPECT_LT(worst, 1e-9);
  const double sketched = RootPathJerk(sketch, root), filled = RootPathJerk(r->clip, root);
  std::printf("root path jerk: sketch %.2f m/s^3, fill %.2f m/s^3\n", sketched, filled);
  EXPECT_LT(filled, 0.6 * sketched);  // measured 27.1 against 83.9 (the capture: 38.9)
  // The height: a smooth curve through its keys that stays between each pair of neighbouring
  // keys (a hip above its keys would ask the planted legs for more reach), kinking less than
  // the sketch's straight segments.
  double height_jerk = 0.0, sketched_height_jerk = 0.0;
  for (size_t k = 0; k + 1 < keys.size(); ++k) {
    const double a = sketch.translation(keys[k], root).y(), b = sketch.translation(keys[k + 1], root).y();
    for (int f = keys[k]; f <= keys[k + 1]; ++f) {
      const double y = r->clip.translation(f, root).y();
      ASSERT_GE(y, std::min(a, b) - 1e-12) << f;
      ASSERT_LE(y, std::max(a, b) + 1e-12) << f;
    }
  }
  for (int f = keys.front() + 2; f + 1 <= keys.back(); ++f) {
    auto jerk = [&](const MotionClip& c) {
      return std::abs(c.translation(f + 1, root).y() - 3.0 * c.translation(f, root).y() +
                      3.0 * c.translation(f - 1, root).y() - c.translation(f - 2, root).y());
    };
    height_jerk += jerk(r->clip);
    sketched_height_jerk += jerk(sketch);
  }
  std::printf("hips height jerk: sketch %.5f, fill %.5f m/frame^3 summed\n", sketched_height_jerk, height_jerk);
  EXPECT_LT(height_jerk, 0.5 * sketched_height_jerk);
  FillOptions plain;
  plain.texture = false;
  Result<FillResult> untextured = engine.Fill(sketch, plain);
  ASSERT_TRUE(untextured.ok());
  for (int f = 0; f < sketch.num_frames; ++f)
    ASSERT_EQ(untextured->clip.translation(f, root), sketch.translation(f, root)) << f;
}

// The hips' height between keys: through keys at uneven spacing on the captured height of the
// default database's first take, the curve meets every key, never leaves the range of the two
// keys around it (no overshoot), rises or falls with them, and does not kink at the keys.
TEST(Fill, HeightCurveThroughUnevenKeysNeitherOvershootsNorKinks) {
  const MotionDatabase& db = DefaultDb();
  const int column = db.RootFeatureChannel(kRootHeight);
  std::vector<int> keys;
  std::vector<double> heights;
  for (int f = 3, step = 4; f < 200; f += step, step = step % 9 + 3) {
    keys.push_back(f);
    heights.push_back(db.signals()(f, column));
  }
  const std::vector<double> curve = MonotoneCubicThroughKeys(keys, heights, 210);
  ASSERT_EQ(curve.size(), 210u);
  EXPECT_EQ(curve[0], heights.front());
  EXPECT_EQ(curve[209], heights.back());
  std::vector<double> linear(210, heights.front());
  for (size_t k = 0; k + 1 < keys.size(); ++k) {
    EXPECT_NEAR(curve[keys[k]], heights[k], 1e-15);
    const double lo = std::min(heights[k], heights[k + 1]), hi = std::max(heights[k], heights[k + 1]);
    for (int f = keys[k]; f <= keys[k + 1]; ++f) {
      ASSERT_GE(curve[f], lo - 1e-15) << f;
      ASSERT_LE(curve[f], hi + 1e-15) << f;
      if (f < keys[k + 1]) {
        ASSERT_GE((curve[f + 1] - curve[f]) * (heights[k + 1] - heights[k]), -1e-18) << f;  // monotone
      }
      linear[f] = heights[k] + (heights[k + 1] - heights[k]) * (f - keys[k]) / (keys[k + 1] - keys[k]);
    }
  }
  for (int f = keys.back(); f < 210; ++f) linear[f] = heights.back();
  // Jerk (third differences) summed: the straight segments kink at every key.
  auto jerk = [](const std::vector<double>& y) {
    double sum = 0.0;
    for (size_t f = 3; f < y.size(); ++f) sum += std::abs(y[f] - 3.0 * y[f - 1] + 3.0 * y[f - 2] - y[f - 3]);
    return sum;
  };
  std::printf("height jerk summed: %.4f m/frame^3 (straight segments: %.4f)\n", jerk(curve), jerk(linear));
  EXPECT_LT(jerk(curve), 0.65 * jerk(linear));  // measured 0.566 against 0.992
}

TEST(Fill, CostMatrixJoinsWithNoMoreSeamsThanBestFragment) {
  const MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  FillOptions options;
  std::map<JoinCriterion, int> seams;
  for (JoinCriterion join : {JoinCriterion::kBestFragment, JoinCriterion::kCostMatrix, JoinCriterion::kBestAnimation}) {
    options.join = join;
    Result<FillResult> r = engine.Fill(sketch, options);
    ASSERT_TRUE(r.ok()) << r.status().message();
    seams[join] = r->report.seams;
    EXPECT_EQ(r->report.join, JoinCriterionName(join));
  }
  EXPECT_LT(seams[JoinCriterion::kCostMatrix], seams[JoinCriterion::kBestFragment]);
  // Best animation follows one clip wherever that clip has candidates and the cost matrix's
  // path between, and each switch is a seam: about as many as best fragment's (measured 89
  // against 86; the cost matrix 54).
  EXPECT_LE(seams[JoinCriterion::kBestAnimation], 1.1 * seams[JoinCriterion::kBestFragment]);
  std::printf("seams: best fragment %d, cost matrix %d, best animation %d\n", seams[JoinCriterion::kBestFragment],
              seams[JoinCriterion::kCostMatrix], seams[JoinCriterion::kBestAnimation]);
}

TEST(Fill, HierarchicalBeatsTheMeanPoseOnACapturedWalkOfAnUnseenStyle) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<Scene> truth = ImportFile(testing::DataPath("bandai-namco-1/data/dataset-1_walk_proud_002.bvh"));
  ASSERT_TRUE(truth.ok());
  const MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  std::map<FillMethod, double> mpjpe;
  for (FillMethod method : {FillMethod::kMean, FillMethod::kHierarchical}) {
    FillOptions options;
    options.method = method;
    Result<FillResult> r = engine.Fill(sketch, options);
    ASSERT_TRUE(r.ok());
    Result<FillMetrics> m = ScoreFill(DefaultDb().skeleton(), truth->clips[0], sketch, r->clip, DefaultDb().root_joint());
    ASSERT_TRUE(m.ok()) << m.status().message();
    mpjpe[method] = m->mpjpe_unkeyed_cm;
    EXPECT_LT(m->bone_length_error, 1e-9);
    // The whole body's jerk against the capture's: issue 15's band for the default method.
    if (method == FillMethod::kHierarchical) {
      const int root = DefaultDb().root_joint();
      const double path = RootPathJerk(r->clip, root) / RootPathJerk(truth->clips[0], root);
      std::printf("jitter ratio %.3f, root path's jerk / capture's %.3f\n", m->jitter_ratio, path);
      EXPECT_GT(m->jitter_ratio, 0.8);  // measured 0.945
      EXPECT_LT(m->jitter_ratio, 1.3);
      // Measured 0.696 (the sketch's own path: 2.155): smoother than the capture, whose hips bob
      // between the keys where the fill's height follows a smooth curve through them.
      EXPECT_GT(path, 0.5);
      EXPECT_LT(path, 1.3);
    }
  }
  // About 9.3 vs 10.5 cm (12% lower) with the 21-clip default database; the full 174-clip
  // database gains more (docs/fill.md).
  EXPECT_LT(mpjpe[FillMethod::kHierarchical], 0.92 * mpjpe[FillMethod::kMean])
      << "hierarchical " << mpjpe[FillMethod::kHierarchical] << " cm, mean " << mpjpe[FillMethod::kMean] << " cm";
}

// Mean third difference (m/s^3) of the unkeyed joints' positions relative to the hips.
double UnkeyedJerk(const MotionClip& sketch, const MotionClip& clip) {
  const Skeleton& s = DefaultDb().skeleton();
  const std::vector<Eigen::Vector3d> p = ComputeWorldPositions(s, clip);
  const int nj = clip.num_joints, hips = DefaultDb().root_joint();
  const double rate = clip.sample_rate_hz;
  double sum = 0.0;
  long count = 0;
  for (int j = 0; j < nj; ++j) {
    if (!sketch.keys[j].rotation_frames.empty() || j == hips || s.parent(j) < 0) continue;
    auto at = [&](int f) { return Eigen::Vector3d(p[f * nj + j] - p[f * nj + hips]); };
    for (int f = 2; f + 1 < clip.num_frames; ++f, ++count)
      sum += (at(f + 1) - 3.0 * at(f) + 3.0 * at(f - 1) - at(f - 2)).norm() * rate * rate * rate;
  }
  return count ? sum / count : 0.0;
}

// The synthesised joints move about as smoothly as the capture: their finest band (above 7.5
// Hz), which holds the blend's own jolts, is left out and fragments cross-fade along a
// smoothstep. Keeping that band makes them markedly jerkier at no gain in accuracy.
TEST(Fill, SynthesisedJointsAreAboutAsSmoothAsTheCapture) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<Scene> truth = ImportFile(testing::DataPath("bandai-namco-1/data/dataset-1_walk_proud_002.bvh"));
  ASSERT_TRUE(truth.ok());
  const MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  const double captured = UnkeyedJerk(sketch, truth->clips[0]);
  std::map<int, double> ratio, mpjpe;
  for (int finest : {0, 1}) {
    FillOptions options;
    options.synthesized_finest_band = finest;
    options.lead_detail = 0.0;  // the blend's own finest band, kept or left out
    Result<FillResult> r = engine.Fill(sketch, options);
    ASSERT_TRUE(r.ok());
    ratio[finest] = UnkeyedJerk(sketch, r->clip) / captured;
    Result<FillMetrics> m = ScoreFill(DefaultDb().skeleton(), truth->clips[0], sketch, r->clip, DefaultDb().root_joint());
    ASSERT_TRUE(m.ok());
    mpjpe[finest] = m->mpjpe_unkeyed_cm;
  }
  std::printf("unkeyed jerk / capture's: %.3f with the finest band, %.3f without; MPJPE %.3f / %.3f cm\n", ratio[0],
              ratio[1], mpjpe[0], mpjpe[1]);
  // Measured 1.125 with the band, 1.068 without; MPJPE 8.845 / 8.829 cm.
  EXPECT_LT(ratio[1], 0.98 * ratio[0]);
  EXPECT_LT(ratio[1], 1.3);  // issue 15's limit for the jitter ratio
  EXPECT_LT(mpjpe[1], mpjpe[0] + 0.05);
}

// The normal style's short run, dash, second walk and walk backwards travel on joint_Root, above
// their hips; sketched with it (sketch_maker.h), they are matched with takes that travel at
// their pace and the default method fills them well below the mean pose. Sketched in place,
// as they were before, runs and dashes took their upper body from bows and guides (measured:
// 9.35 cm against the mean pose's 9.78).
TEST(Fill, TakesTravellingOnARootBoneAboveTheHipsBeatTheMeanPose) {
  MOCAPFILL_REQUIRE_CORPUS();
  const MotionDatabase& db = testing::BandaiDbWithout("normal");
  FillEngine engine(db);
  std::vector<FillOptions> variants(2);
  variants[0].method = FillMethod::kMean;
  Result<std::vector<std::vector<FillMetrics>>> m = testing::FillHeldOutTakes(
      engine, db, "legs8", {"run_normal_001", "dash_normal_001", "walk_normal_002", "walk-back_normal_001"}, variants);
  ASSERT_TRUE(m.ok()) << m.status().message();
  const testing::VariantScores scores = testing::ScoreVariants(*m);
  std::printf("legs8, the normal style's root-bone takes: mean pose %.3f cm, hierarchical %.3f cm\n",
              scores.mpjpe_cm[0], scores.mpjpe_cm[1]);
  EXPECT_LT(scores.mpjpe_cm[1], 0.8 * scores.mpjpe_cm[0]);  // measured 6.562 against 9.783 cm
  EXPECT_LT(scores.key_error_max_deg, 0.01);
}

// The blend of 128 takes averages their detail away (the upper body's jerk was 0.54 - 0.67 of
// the capture's on the tuning half); its lead take's finest band, put back at lead_detail,
// lifts the jitter ratio into issue 15's [0.8, 1.3] without moving the pose. Held-out takes: against a
// database with their own style the blend is about as jerky as the capture already.
TEST(Fill, LeadDetailBringsTheJitterOfHeldOutTakesTowardsTheCaptures) {
  MOCAPFILL_REQUIRE_CORPUS();
  const MotionDatabase& db = testing::BandaiDbWithout("proud");
  FillEngine engine(db);
  std::vector<FillOptions> variants(2);
  variants[0].lead_detail = 0.0;
  const std::vector<std::string> takes = {"walk_proud_001", "run_proud_001", "bow_proud_001", "bye_proud_001",
                                          "guide_proud_001"};
  for (const char* scenario : {"legs8", "root"}) {
    Result<std::vector<std::vector<FillMetrics>>> m = testing::FillHeldOutTakes(engine, db, scenario, takes, variants);
    ASSERT_TRUE(m.ok()) << m.status().message();
    std::vector<double> jitter(2, 0.0), mpjpe(2, 0.0);
    double key_error = 0.0;
    for (const std::vector<FillMetrics>& take : *m)
      for (size_t v = 0; v < 2; ++v) {
        jitter[v] += take[v].jitter_ratio / takes.size();
        mpjpe[v] += take[v].mpjpe_unkeyed_cm;
        key_error = std::max(key_error, take[v].key_error_max_deg);
      }
    std::printf("%s: jitter ratio %.3f without the lead's detail, %.3f with %.1f of it; MPJPE summed %.3f / %.3f cm\n",
                scenario, jitter[0], jitter[1], variants[1].lead_detail, mpjpe[0], mpjpe[1]);
    EXPECT_GT(variants[1].lead_detail, 0.0);
    // Measured: legs8 0.635 -> 0.847, root 0.825 -> 1.160; MPJPE 33.263 -> 33.279, 36.599 -> 36.614.
    EXPECT_GT(jitter[1], jitter[0] + 0.1) << scenario;
    EXPECT_GE(jitter[1], 0.8) << scenario;  // issue 15's range for the jitter ratio
    EXPECT_LE(jitter[1], 1.3) << scenario;
    EXPECT_LT(mpjpe[1], 1.005 * mpjpe[0]) << scenario;
    EXPECT_LT(key_error, 0.01) << scenario;
  }
}

// Timid gestures of a style the database lacks (not-confident), hips and arms keyed every 8
// frames: their keyed arms take the detail of livelier takes scaled to how much their
// keys move them (texture_activity_window_s), so they tremble less, nearer the capture,
// and come nearer it between keys; keys stay exact.
TEST(Fill, TimidGesturesTakeDetailAsLivelyAsTheirKeys) {
  MOCAPFILL_REQUIRE_CORPUS();
  const MotionDatabase& db = testing::BandaiDbWithout("not-confident");
  FillEngine engine(db);
  std::vector<FillOptions> variants(2);
  variants[0].texture_activity_window_s = 0.0;
  const std::vector<std::string> takes = {"bow_not-confident_001", "bye_not-confident_001",
                                          "byebye_not-confident_001", "guide_not-confident_001"};
  Result<std::vector<std::vector<FillMetrics>>> m = testing::FillHeldOutTakes(engine, db, "root-arms", takes, variants);
  ASSERT_TRUE(m.ok()) << m.status().message();
  std::vector<double> jitter(2, 0.0), between(2, 0.0);
  double key_error = 0.0;
  for (const std::vector<FillMetrics>& take : *m)
    for (size_t v = 0; v < 2; ++v) {
      jitter[v] += take[v].jitter_ratio / takes.size();
      between[v] += take[v].mpjpe_keyed_between_cm / takes.size();
      key_error = std::max(key_error, take[v].key_error_max_deg);
    }
  std::printf("root-arms: jitter ratio %.3f with the takes' detail unscaled, %.3f scaled; keyed joints between keys "
              "%.3f / %.3f cm\n", jitter[0], jitter[1], between[0], between[1]);
  EXPECT_GT(variants[1].texture_activity_window_s, 0.0);
  // Measured 1.432 -> 1.358, 5.958 -> 5.940 cm.
  EXPECT_LT(jitter[1], 0.97 * jitter[0]);
  EXPECT_LT(between[1], between[0]);
  EXPECT_LT(key_error, 0.01);
}

// With the legs synthesised (the upper-body scenario: hips, torso, head and arms keyed every 8
// frames) the leg chains blend at most leg_blend candidates while other groups blend all 160:
// many takes' strides of slightly different phase average into a blurred step. Over the
// locomotion of a style the database lacks, the legs come nearer the capture.
TEST(Fill, SynthesisedLegsBlendFewerCandidates) {
  MOCAPFILL_REQUIRE_CORPUS();
  const MotionDatabase& db = testing::BandaiDbWithout("proud");
  FillEngine engine(db);
  std::vector<FillOptions> variants(2);
  for (FillOptions& options : variants)
    options.swing_gain = 1.0;  // the steps as blended: the gain puts back part of what a wide blend blurs
  variants[1].leg_blend = 128;
  const std::vector<std::string> takes = {"walk_proud_001",       "walk_proud_002", "walk-back_proud_001",
                                          "walk-left_proud_001", "walk-right_proud_001"};
  Result<std::vector<std::vector<FillMetrics>>> m =
      testing::FillHeldOutTakes(engine, db, "upper-body", takes, variants);
  ASSERT_TRUE(m.ok()) << m.status().message();
  const testing::VariantScores scores = testing::ScoreVariants(*m);
  EXPECT_LT(scores.key_error_max_deg, 0.01);
  std::printf("legs MPJPE %.3f cm blending 32, %.3f cm blending 128 (feet %.2f / %.2f cm/s on the capture's "
              "contacts)\n",
              scores.mpjpe_cm[0], scores.mpjpe_cm[1], scores.skate_cm_per_s[0], scores.skate_cm_per_s[1]);
  EXPECT_LT(scores.mpjpe_cm[0], 0.97 * scores.mpjpe_cm[1]);  // measured 8.799 against 9.238 cm

  // Each leg source reports at most leg_blend blended candidates, the other groups up to blend.
  Result<Scene> truth = ImportFile(testing::DataPath("bandai-namco-1/data/dataset-1_walk_proud_001.bvh"));
  ASSERT_TRUE(truth.ok());
  Result<SketchScenario> scenario = FindSketchScenario("upper-body");
  ASSERT_TRUE(scenario.ok());
  Result<MotionClip> sketch = MakeSketch(db.skeleton(), truth->clips[0], scenario->sketch);
  ASSERT_TRUE(sketch.ok()) << sketch.status().message();
  Result<FillResult> r = engine.Fill(*sketch, variants[0]);
  ASSERT_TRUE(r.ok()) << r.status().message();
  int leg_sources = 0;
  for (const FragmentSource& source : r->report.fragments) {
    const bool leg = source.group.find("Leg") != std::string::npos;
    leg_sources += leg ? 1 : 0;
    EXPECT_LE(source.blended, leg ? variants[0].leg_blend : variants[0].blend) << source.group;
  }
  EXPECT_GT(leg_sources, 10);
}

// Root and legs keyed every 8 frames on standing gestures of a style the database lacks: each
// group's candidates are matched with the root's planar velocity weighing travel_weight times as
// much as its other drivers, so the torso, head and arms of a sketch that stands are blended
// from takes that stand rather than partly from walks whose legs happen to hold a similar pose:
// the blended takes' speed (the report's travel_mps) falls. Whether that lowers the error is
// for the protocol to say (docs/fill.md: gestures better in 11 of the 15 held-out styles; this
// one, proud, is among the four that are not).
TEST(Fill, StandingSketchesTakeTheirUpperBodyFromStandingTakes) {
  MOCAPFILL_REQUIRE_CORPUS();
  const MotionDatabase& db = testing::BandaiDbWithout("proud");
  Result<SketchScenario> scenario = FindSketchScenario("legs8");
  ASSERT_TRUE(scenario.ok());
  FillEngine engine(db);
  std::map<double, double> travel;  // per weight: the upper body's blended takes' speed, mean over fragments
  std::map<double, int> fragments;
  for (const char* take : {"bow_proud_001", "bye_proud_001", "byebye_proud_001", "guide_proud_001"}) {
    Result<Scene> truth = ImportFile(testing::DataPath(std::string("bandai-namco-1/data/dataset-1_") + take + ".bvh"));
    ASSERT_TRUE(truth.ok());
    Result<MotionClip> sketch = MakeSketch(db.skeleton(), truth->clips[0], scenario->sketch);
    ASSERT_TRUE(sketch.ok());
    for (double weight : {1.0, FillOptions{}.travel_weight}) {
      FillOptions options;
      options.travel_weight = weight;
      Result<FillResult> r = engine.Fill(*sketch, options);
      ASSERT_TRUE(r.ok()) << r.status().message();
      for (const FragmentSource& source : r->report.fragments) {
        if (source.group.find("Leg") != std::string::npos) continue;
        EXPECT_GE(source.travel_mps, 0.0);
        travel[weight] += source.travel_mps;
        ++fragments[weight];
      }
    }
  }
  const double weighed = FillOptions{}.travel_weight;
  for (double weight : {1.0, weighed}) travel[weight] /= std::max(1, fragments[weight]);
  std::printf("standing gestures: the upper body's blended takes travel at %.3f m/s with the root's travel weighed "
              "1 time, %.3f m/s weighed %.0f times\n",
              travel[1.0], travel[weighed], weighed);
  EXPECT_GT(fragments[weighed], 20);
  EXPECT_LT(travel[weighed], 0.75 * travel[1.0]);  // measured 0.053 against 0.083 m/s
}

// Hips and legs keyed every 16 frames on the locomotion of a style the database lacks. Where
// the root moves the keyed legs already carry the gait, and weighing the root's speed six times
// as well drew the torso and arms from takes of the sketch's pace but another gait: moving
// fragments now weigh it like any other driver (moving_travel_weight 1), and the unkeyed joints
// come closer to the capture. Sketches that stand match as before: their fills are identical.
TEST(Fill, MovingSketchesWithKeyedLegsTakeTheirUpperBodyByGaitNotPace) {
  MOCAPFILL_REQUIRE_CORPUS();
  const MotionDatabase& db = testing::BandaiDbWithout("proud");
  FillEngine engine(db);
  FillOptions weighed;  // before: the moving upper body matched with the travel weighed like standing
  weighed.moving_travel_weight = weighed.travel_weight;
  const std::vector<std::string> locomotion = {"walk_proud_001",      "walk_proud_002", "walk-left_proud_001",
                                               "walk-right_proud_001", "run_proud_001",  "dash_proud_001"};
  Result<std::vector<std::vector<FillMetrics>>> moving =
      testing::FillHeldOutTakes(engine, db, "legs16", locomotion, {FillOptions{}, weighed});
  ASSERT_TRUE(moving.ok()) << moving.status().message();
  double by_gait = 0.0, by_pace = 0.0;
  for (const std::vector<FillMetrics>& take : *moving) {
    by_gait += take[0].mpjpe_unkeyed_cm / locomotion.size();
    by_pace += take[1].mpjpe_unkeyed_cm / locomotion.size();
    EXPECT_LT(take[0].key_error_max_deg, 0.01);
  }
  std::printf("held-out locomotion, legs16: unkeyed joints %.3f cm matched by gait, %.3f cm with the pace weighed\n",
              by_gait, by_pace);
  EXPECT_LT(by_gait, 0.99 * by_pace);  // measured 6.963 against 7.069 cm (6.943 / 7.088 blending 128 candidates)

  Result<std::vector<std::vector<FillMetrics>>> standing =
      testing::FillHeldOutTakes(engine, db, "legs16", {"bow_proud_001", "bye_proud_001"}, {FillOptions{}, weighed});
  ASSERT_TRUE(standing.ok()) << standing.status().message();
  for (const std::vector<FillMetrics>& take : *standing) EXPECT_EQ(take[0].mpjpe_unkeyed_cm, take[1].mpjpe_unkeyed_cm);
}

// The legs synthesised under a keyed upper body (the upper-body scenario), on every take of a
// style the database lacks: each leg chain is matched on the hips it hangs from (the keyed root
// leads its drivers, leg_drivers 2) rather than on the joints the correlation table ranks first
// (the chest and spine, which bend with the arms): a bow's or a wave's stance and a walk's
// steps come from takes whose pelvis moves as the sketch's does.
TEST(Fill, SynthesisedLegsAreMatchedOnTheHipsTheyHangFrom) {
  MOCAPFILL_REQUIRE_CORPUS();
  const MotionDatabase& db = testing::BandaiDbWithout("proud");
  FillEngine engine(db);
  std::vector<FillOptions> variants(2);
  variants[1].leg_drivers = 0;  // before: as every other group, by correlation
  const std::vector<std::string> takes = {
      "bow_proud_001",       "bye_proud_001",        "byebye_proud_001", "guide_proud_001",
      "dash_proud_001",      "run_proud_001",        "walk-back_proud_001", "walk-left_proud_001",
      "walk-right_proud_001", "walk_proud_001",      "walk_proud_002"};
  Result<std::vector<std::vector<FillMetrics>>> m =
      testing::FillHeldOutTakes(engine, db, "upper-body", takes, variants);
  ASSERT_TRUE(m.ok()) << m.status().message();
  const testing::VariantScores scores = testing::ScoreVariants(*m);
  EXPECT_LT(scores.key_error_max_deg, 0.01);
  std::printf("upper-body scenario, legs unkeyed: %.3f cm (feet %.2f cm/s on the capture's contacts) on the hips, "
              "%.3f cm (%.2f cm/s) by correlation\n",
              scores.mpjpe_cm[0], scores.skate_cm_per_s[0], scores.mpjpe_cm[1], scores.skate_cm_per_s[1]);
  // Measured 8.530 against 11.786 cm (8.553 / 11.727 before the sway, gait_sway.h; feet left free).
  EXPECT_LT(scores.mpjpe_cm[0], 0.8 * scores.mpjpe_cm[1]);
}

}  // namespace
}  // namespace mocapfill
