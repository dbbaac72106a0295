// The PCA-based fill methods: `pca` (closed form) and `hybrid`
// (fragments, guided Ceres fit, texture, edits) on the embedded default database
// (fixtures/default_db: Bandai-Namco locomotion of three styles) and the shipped sketch of a
// walk in a style that database does not hold (fixtures/sketches).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "formats/motion_io.h"
#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "processing/evaluation/metrics.h"
#include "processing/fill/fill_engine.h"
#include "processing/hybrid/hybrid_fill.h"
#include "processing/pca/pca_model_builder.h"
#include "tests/support/default_db.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

namespace fs = std::filesystem;

constexpr double kExactDeg = 1e-6;          // full-pose keys: rounding only
constexpr double kSubspaceKeyMeanDeg = 0.5;  // target mean key error of the subspace variant
constexpr double kPositionKeyCm = 1.0;      // target: keyed feet within 1 cm

using testing::DefaultDb;

// The shipped glTF sketch (hips and legs keyed every 8 frames) in database joint order.
MotionClip Sketch() { return testing::ShippedSketchOnDefaultDbRig(); }

// Key error over the sketch's rotation keys, degrees: {mean, max}.
std::pair<double, double> KeyErrorDeg(const MotionClip& sketch, const MotionClip& out) {
  double sum = 0.0, worst = 0.0;
  int count = 0;
  for (int j = 0; j < sketch.num_joints; ++j)
    for (int f : sketch.keys[j].rotation_frames) {
      const double e = GeodesicAngle(sketch.rotation(f, j), out.rotation(f, j)) * kDegPerRad;
      sum += e;
      worst = std::max(worst, e);
      ++count;
    }
  return {count ? sum / count : 0.0, worst};
}

// Mean angular acceleration (deg per frame^2) of the joints the sketch does not key: the
// size of the second difference of local rotations, a jitter measure needing no truth.
double UnkeyedAccelerationDeg(const MotionClip& sketch, const MotionClip& out) {
  double sum = 0.0;
  int count = 0;
  for (int j = 0; j < out.num_joints; ++j) {
    if (!sketch.keys[j].rotation_frames.empty()) continue;
    for (int f = 1; f + 1 < out.num_frames; ++f) {
      const Eigen::Vector3d a = LogMap(out.rotation(f - 1, j).conjugate() * out.rotation(f, j));
      const Eigen::Vector3d b = LogMap(out.rotation(f, j).conjugate() * out.rotation(f + 1, j));
      sum += (b - a).norm() * kDegPerRad;
      ++count;
    }
  }
  return sum / std::max(1, count);
}

double MeanUnkeyedAngleDeg(const MotionClip& sketch, const MotionClip& a, const MotionClip& b) {
  double sum = 0.0;
  int count = 0;
  for (int j = 0; j < a.num_joints; ++j) {
    if (!sketch.keys[j].rotation_frames.empty()) continue;
    for (int f = 0; f < a.num_frames; ++f, ++count) sum += GeodesicAngle(a.rotation(f, j), b.rotation(f, j)) * kDegPerRad;
  }
  return sum / std::max(1, count);
}

FillOptions Hybrid() {
  FillOptions options;
  options.method = FillMethod::kHybrid;
  return options;
}

FillOptions Subspace() {
  FillOptions options = Hybrid();
  options.pca.fit.full_pose = false;
  return options;
}

TEST(HybridFill, OptionsNamesAndValidation) {
  EXPECT_EQ(*ParseFillMethod("hybrid"), FillMethod::kHybrid);
  EXPECT_EQ(*ParseFillMethod("pca"), FillMethod::kPca);
  EXPECT_STREQ(FillMethodName(FillMethod::kHybrid), "hybrid");
  FillOptions options = Hybrid();
  EXPECT_TRUE(options.Validate().ok());
  options.pca.band_gains = {1.0, -2.0};
  EXPECT_NE(options.Validate().message().find("band_gains[1]"), std::string::npos) << options.Validate().message();
  options = Hybrid();
  options.pca.fit.fit.guide_sigma_deg = 0.0;
  EXPECT_EQ(options.Validate().code(), ErrorCode::kInvalidArgument);
}

TEST(HybridFill, SubspaceVariantKeepsKeysAndReportsTheSolver) {
  const MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  Result<FillResult> r = engine.Fill(sketch, Subspace());
  ASSERT_TRUE(r.ok()) << r.status().message();
  const auto [mean, worst] = KeyErrorDeg(sketch, r->clip);
  std::printf("hybrid (subspace) key error: mean %.2e, max %.2e deg\n", mean, worst);
  EXPECT_LT(mean, kSubspaceKeyMeanDeg);
  EXPECT_NEAR(r->report.key_error_mean_deg, mean, 1e-9);
  EXPECT_EQ(r->report.method, "hybrid");
  EXPECT_EQ(r->report.pca_model_source, "built from the database");
  EXPECT_GT(r->report.pca_components, 0);
  ASSERT_TRUE(r->report.has_solver);
  EXPECT_TRUE(r->report.solver.converged) << r->report.solver.message;
  EXPECT_GE(r->report.solver.iterations, 1);
  EXPECT_LE(r->report.solver.final_cost, r->report.solver.initial_cost);
  std::vector<std::string> stages;
  for (const StageTime& t : r->report.stages) stages.push_back(t.stage);
  for (const char* stage : {"pca_model", "fragments", "fragments.match", "pca_fit", "hybrid_texture"})
    EXPECT_NE(std::find(stages.begin(), stages.end(), stage), stages.end()) << stage;
  EXPECT_GT(r->report.sketch_fragments, 0);  // the fragment stage's report is carried over
}

TEST(HybridFill, WithoutRepinningTheSubspaceFitMissesKeysAndRepinningRestoresThem) {
  const MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  FillOptions options = Subspace();
  options.texture = false;
  options.repin_keys = false;
  Result<FillResult> raw = engine.Fill(sketch, options);
  ASSERT_TRUE(raw.ok()) << raw.status().message();
  options.repin_keys = true;
  Result<FillResult> pinned = engine.Fill(sketch, options);
  ASSERT_TRUE(pinned.ok()) << pinned.status().message();
  const double raw_mean = KeyErrorDeg(sketch, raw->clip).first, pinned_mean = KeyErrorDeg(sketch, pinned->clip).first;
  std::printf("subspace fit key error: %.3f deg mean before re-pinning, %.2e after\n", raw_mean, pinned_mean);
  EXPECT_GT(raw_mean, kSubspaceKeyMeanDeg);  // the subspace alone cannot hold the keys
  EXPECT_LT(pinned_mean, 1e-3);
}

TEST(HybridFill, FullPoseVariantHoldsKeysExactly) {
  const MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  for (bool texture : {false, true}) {
    FillOptions options = Hybrid();
    options.pca.fit.full_pose = true;
    options.texture = texture;
    options.repin_keys = texture;  // without texture the full-pose fit alone must hold them
    Result<FillResult> r = engine.Fill(sketch, options);
    ASSERT_TRUE(r.ok()) << r.status().message();
    EXPECT_LT(KeyErrorDeg(sketch, r->clip).second, kExactDeg) << "texture " << texture;
  }
}

TEST(HybridFill, DiffersFromHierarchicalAndIsSmootherThanAJitteryVariant) {
  const MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  FillOptions hierarchical;
  Result<FillResult> h = engine.Fill(sketch, hierarchical);
  Result<FillResult> y = engine.Fill(sketch, Hybrid());
  FillOptions jittery = Hybrid();
  jittery.pca.band_gains = {4.0, 4.0};  // the two highest bands amplified after the fill
  Result<FillResult> j = engine.Fill(sketch, jittery);
  ASSERT_TRUE(h.ok() && y.ok() && j.ok());
  const double moved = MeanUnkeyedAngleDeg(sketch, h->clip, y->clip);
  const double acc_h = UnkeyedAccelerationDeg(sketch, h->clip), acc_y = UnkeyedAccelerationDeg(sketch, y->clip),
               acc_j = UnkeyedAccelerationDeg(sketch, j->clip);
  std::printf("hybrid vs hierarchical: %.2f deg apart on unkeyed joints; acceleration %.4f (hierarchical %.4f, "
              "jittery %.4f) deg/frame^2\n", moved, acc_y, acc_h, acc_j);
  EXPECT_GT(moved, 0.5);
  EXPECT_LT(acc_y, 0.7 * acc_j);
}

TEST(HybridFill, GivenModelIsUsedAndBuiltModelGivesTheSameResult) {
  const MotionClip sketch = Sketch();
  Result<PcaModel> model = BuildPcaModel(DefaultDb(), {});
  ASSERT_TRUE(model.ok());
  FillEngine given_engine(DefaultDb());
  given_engine.SetPcaModel(&*model);
  Result<FillResult> given = given_engine.Fill(sketch, Hybrid());
  FillEngine engine(DefaultDb());
  Result<FillResult> built = engine.Fill(sketch, Hybrid());
  ASSERT_TRUE(given.ok() && built.ok()) << given.status().message();
  EXPECT_EQ(given->report.pca_model_source, "given");
  EXPECT_LT(MeanUnkeyedAngleDeg(sketch, given->clip, built->clip), 1e-9);
}

TEST(HybridFill, ComponentDialsChangeTheMotion) {
  const MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  Result<FillResult> plain = engine.Fill(sketch, Hybrid());
  FillOptions dialled = Hybrid();
  dialled.pca.dials = {{0, 2.0}};
  Result<FillResult> edited = engine.Fill(sketch, dialled);
  ASSERT_TRUE(plain.ok() && edited.ok()) << edited.status().message();
  EXPECT_GT(MeanUnkeyedAngleDeg(sketch, plain->clip, edited->clip), 1.0);
  dialled.pca.dials = {{1000, 1.0}};
  EXPECT_EQ(engine.Fill(sketch, dialled).status().code(), ErrorCode::kInvalidArgument);
}

TEST(HybridFill, FootPositionKeysHoldWithinACentimetre) {
  // Hips keyed only; the feet placed where the captured sketch has them at every key.
  MotionClip sketch = Sketch();
  const Skeleton& skeleton = DefaultDb().skeleton();
  const std::vector<Eigen::Vector3d> world = ComputeWorldPositions(skeleton, sketch);
  const int hips = *skeleton.Find("Hips");
  std::vector<SketchPositionKey> keys;
  for (const char* foot : {"Foot_L", "Foot_R"}) {
    const int j = *skeleton.Find(foot);
    for (int f : sketch.keys[hips].rotation_frames)
      keys.push_back({f, foot, world[static_cast<size_t>(f) * skeleton.num_joints() + j]});
  }
  for (int j = 0; j < skeleton.num_joints(); ++j)
    if (j != hips) sketch.keys[j] = JointKeys{};
  FillEngine engine(DefaultDb());
  for (bool full_pose : {false, true}) {
    FillOptions options = Hybrid();
    options.pca.fit.full_pose = full_pose;
    Result<FillResult> r = engine.Fill(sketch, options, keys);
    ASSERT_TRUE(r.ok()) << r.status().message();
    const std::vector<Eigen::Vector3d> out = ComputeWorldPositions(skeleton, r->clip);
    double worst = 0.0;
    for (const SketchPositionKey& k : keys) {
      const int j = *skeleton.Find(k.joint);
      worst = std::max(worst, 100.0 * (out[static_cast<size_t>(k.frame) * skeleton.num_joints() + j] - k.position_m).norm());
    }
    std::printf("foot position keys (%s): max error %.3f cm over %zu keys\n", full_pose ? "full-pose" : "subspace",
                worst, keys.size());
    EXPECT_LT(worst, kPositionKeyCm);
  }
  FillOptions hierarchical;
  EXPECT_EQ(engine.Fill(sketch, hierarchical, keys).status().code(), ErrorCode::kInvalidArgument);
}

TEST(PcaFill, ClosedFormKeepsKeysAndMovesTheUpperBody) {
  const MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  FillOptions pca;
  pca.method = FillMethod::kPca;
  FillOptions mean;
  mean.method = FillMethod::kMean;
  Result<FillResult> p = engine.Fill(sketch, pca);
  Result<FillResult> m = engine.Fill(sketch, mean);
  ASSERT_TRUE(p.ok() && m.ok()) << p.status().message();
  EXPECT_LT(KeyErrorDeg(sketch, p->clip).second, kExactDeg);
  EXPECT_EQ(p->report.method, "pca");
  EXPECT_GT(MeanUnkeyedAngleDeg(sketch, p->clip, m->clip), 1.0);  // not the mean pose
}

TEST(HybridFill, RejectsAModelThatDoesNotFitTheDatabaseSkeleton) {
  Result<PcaModel> model = BuildPcaModel(DefaultDb(), {});
  ASSERT_TRUE(model.ok());
  model->joint_names[3] = "NoSuchJoint";
  FragmentFillEngine fragments(DefaultDb());
  const FillOptions options = Hybrid();
  FragmentFillReport report;
  Result<HybridResult> r = HybridFill(fragments, *model, Sketch(), options, options.pca, {}, report);
  EXPECT_EQ(r.status().code(), ErrorCode::kInvalidArgument);
  EXPECT_NE(r.status().message().find("NoSuchJoint"), std::string::npos) << r.status().message();
}

TEST(HybridFill, CapturedWalkOfAnUnseenStyleBeatsTheMeanPose) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<Scene> truth = ImportFile(testing::DataPath("bandai-namco-1/data/dataset-1_walk_proud_002.bvh"));
  ASSERT_TRUE(truth.ok());
  const MotionClip sketch = Sketch();
  FillEngine engine(DefaultDb());
  std::map<FillMethod, FillMetrics> metrics;
  for (FillMethod method : {FillMethod::kMean, FillMethod::kHierarchical, FillMethod::kPca, FillMethod::kHybrid}) {
    FillOptions options;
    options.method = method;
    Result<FillResult> r = engine.Fill(sketch, options);
    ASSERT_TRUE(r.ok()) << r.status().message();
    Result<FillMetrics> m = ScoreFill(DefaultDb().skeleton(), truth->clips[0], sketch, r->clip, DefaultDb().root_joint());
    ASSERT_TRUE(m.ok()) << m.status().message();
    metrics[method] = *m;
    std::printf("%-12s unkeyed %.3f cm, jitter ratio %.3f\n", FillMethodName(method), m->mpjpe_unkeyed_cm,
                m->jitter_ratio);
    EXPECT_LT(m->bone_length_error, 1e-9);
  }
  EXPECT_LT(metrics[FillMethod::kHybrid].mpjpe_unkeyed_cm, metrics[FillMethod::kMean].mpjpe_unkeyed_cm);
}

}  // namespace
}  // namespace mocapfill
