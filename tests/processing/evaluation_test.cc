// Sketch making and fill metrics on a real Bandai-Namco walk (shared corpus).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "formats/motion_io.h"
#include "processing/evaluation/loso.h"
#include "processing/evaluation/metrics.h"
#include "processing/evaluation/sketch_maker.h"
#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

constexpr double kExactDeg = 1e-6;

const char* kLegs[] = {"Hips", "UpperLeg_L", "LowerLeg_L", "Foot_L", "Toes_L",
                       "UpperLeg_R", "LowerLeg_R", "Foot_R", "Toes_R"};

Scene LoadWalk() {
  Result<Scene> scene = ImportFile(testing::DataPath("bandai-namco-1/data/dataset-1_walk_normal_001.bvh"));
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  return scene.ok() ? std::move(*scene) : Scene{};
}

SketchSpec LegSpec() {
  SketchSpec spec;
  spec.keep_joints.assign(std::begin(kLegs), std::end(kLegs));
  spec.key_every_frames = 8;
  return spec;
}

TEST(SketchMaker, KeyFramesIncludeTheLastFrame) {
  EXPECT_EQ(SketchKeyFrames(20, 8), (std::vector<int>{0, 8, 16, 19}));
  EXPECT_EQ(SketchKeyFrames(17, 8), (std::vector<int>{0, 8, 16}));
}

TEST(SketchMaker, RejectsUnknownJointsAndBadSpacing) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Scene walk = LoadWalk();
  SketchSpec spec = LegSpec();
  spec.keep_joints.push_back("Tail");
  EXPECT_EQ(MakeSketch(walk.skeleton, walk.clips[0], spec).status().code(), ErrorCode::kInvalidArgument);
  spec = LegSpec();
  spec.key_every_frames = 0;
  EXPECT_EQ(MakeSketch(walk.skeleton, walk.clips[0], spec).status().code(), ErrorCode::kInvalidArgument);
}

TEST(SketchMaker, KeepsListedJointsAtKeysAndDropsTheRest) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Scene walk = LoadWalk();
  const MotionClip& truth = walk.clips[0];
  Result<MotionClip> sketch = MakeSketch(walk.skeleton, truth, LegSpec());
  ASSERT_TRUE(sketch.ok()) << sketch.status().message();
  const int hips = *walk.skeleton.Find("Hips"), hand = *walk.skeleton.Find("Hand_L");
  EXPECT_EQ(sketch->keys[hips].rotation_frames, SketchKeyFrames(truth.num_frames, 8));
  EXPECT_EQ(sketch->keys[hips].translation_frames, SketchKeyFrames(truth.num_frames, 8));
  EXPECT_TRUE(sketch->keys[hand].empty());
  for (int f : sketch->keys[hips].rotation_frames) {
    EXPECT_LT(GeodesicAngle(sketch->rotation(f, hips), truth.rotation(f, hips)) * kDegPerRad, kExactDeg);
    EXPECT_LT((sketch->translation(f, hips) - truth.translation(f, hips)).norm(), 1e-12);
  }
  // Between keys the sketch is the slerp, which differs from the capture.
  EXPECT_GT(GeodesicAngle(sketch->rotation(4, hips), truth.rotation(4, hips)), 0.0);
  EXPECT_LT(GeodesicAngle(sketch->rotation(30, hand), walk.skeleton.joint(hand).rest_rotation), 1e-12);
}

// Four short takes of the corpus (the normal style's run, dash, second walk and walk backwards)
// carry their travel on joint_Root, above the hips. The sketch keys that root bone too, so its
// hips travel as captured; joints between two kept ones (the spine under kept arms) stay dropped.
TEST(SketchMaker, KeepsTheTravelOfARootBoneAboveTheHips) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<Scene> run = ImportFile(testing::DataPath("bandai-namco-1/data/dataset-1_run_normal_001.bvh"));
  ASSERT_TRUE(run.ok()) << run.status().message();
  const Skeleton& skeleton = run->skeleton;
  const MotionClip& truth = run->clips[0];
  SketchSpec spec = LegSpec();
  spec.keep_joints.insert(spec.keep_joints.end(), {"UpperArm_L", "LowerArm_L", "Hand_L"});
  Result<MotionClip> sketch = MakeSketch(skeleton, truth, spec);
  ASSERT_TRUE(sketch.ok()) << sketch.status().message();
  const int root = *skeleton.Find("joint_Root"), hips = *skeleton.Find("Hips");
  EXPECT_EQ(sketch->keys[root].translation_frames, SketchKeyFrames(truth.num_frames, 8));
  EXPECT_TRUE(sketch->keys[*skeleton.Find("Chest")].empty());
  WorldPose captured, sketched;
  for (int f : sketch->keys[hips].rotation_frames) {
    ComputeWorldPose(skeleton, truth, f, captured);
    ComputeWorldPose(skeleton, *sketch, f, sketched);
    EXPECT_LT((sketched.positions[hips] - captured.positions[hips]).norm(), 1e-9) << "frame " << f;
  }
  ComputeWorldPose(skeleton, *sketch, 0, captured);
  ComputeWorldPose(skeleton, *sketch, truth.num_frames - 1, sketched);
  const Eigen::Vector3d travel = sketched.positions[hips] - captured.positions[hips];
  EXPECT_GT(std::hypot(travel.x(), travel.z()), 1.5);  // 24 frames at 2.5 - 2.8 m/s
}

TEST(FillMetrics, TruthAgainstItselfScoresZero) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Scene walk = LoadWalk();
  const MotionClip& truth = walk.clips[0];
  const MotionClip sketch = *MakeSketch(walk.skeleton, truth, LegSpec());
  Result<FillMetrics> m = ScoreFill(walk.skeleton, truth, sketch, truth, *walk.skeleton.Find("Hips"));
  ASSERT_TRUE(m.ok());
  EXPECT_EQ(m->unkeyed_joints, 12);  // Bandai upper body: spine to hands
  EXPECT_DOUBLE_EQ(m->mpjpe_unkeyed_cm, 0.0);
  EXPECT_DOUBLE_EQ(m->mpjpe_keyed_between_cm, 0.0);
  EXPECT_DOUBLE_EQ(m->npss, 0.0);
  EXPECT_NEAR(m->jitter_ratio, 1.0, 1e-12);
  EXPECT_LT(m->foot_skate_cm_per_s, 4.25);  // contacts are frames slower than that
  EXPECT_DOUBLE_EQ(m->key_error_max_deg, 0.0);
  EXPECT_DOUBLE_EQ(m->bone_length_error, 0.0);
}

TEST(FillMetrics, SketchAgainstTruthMeasuresTheMissingUpperBody) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Scene walk = LoadWalk();
  const MotionClip& truth = walk.clips[0];
  const MotionClip sketch = *MakeSketch(walk.skeleton, truth, LegSpec());
  Result<FillMetrics> m = ScoreFill(walk.skeleton, truth, sketch, sketch, *walk.skeleton.Find("Hips"));
  ASSERT_TRUE(m.ok());
  // Upper body at the rest pose: tens of centimetres off; legs slerped: a few centimetres.
  EXPECT_GT(m->mpjpe_unkeyed_cm, 10.0);
  EXPECT_GT(m->mpjpe_keyed_between_cm, 0.1);
  EXPECT_LT(m->mpjpe_keyed_between_cm, 5.0);
  EXPECT_GT(m->npss, 0.0);
  EXPECT_DOUBLE_EQ(m->key_error_max_deg, 0.0);
  EXPECT_LT(m->bone_length_error, 1e-9);
}

TEST(FillMetrics, NpssIsZeroForEqualSpectraAndGrowsWithDifference) {
  std::vector<std::vector<double>> a(1, std::vector<double>(64)), b = a, c = a;
  for (int t = 0; t < 64; ++t) {
    a[0][t] = std::sin(2 * kPi * 2 * t / 64.0);
    b[0][t] = std::sin(2 * kPi * 4 * t / 64.0);
    c[0][t] = std::sin(2 * kPi * 8 * t / 64.0);
  }
  EXPECT_DOUBLE_EQ(Npss(a, a), 0.0);
  EXPECT_GT(Npss(a, b), 0.0);
  EXPECT_GT(Npss(a, c), Npss(a, b));
}

}  // namespace
}  // namespace mocapfill

namespace mocapfill {
namespace {

// Summaries pool foot skating over contact frames: a run with few contact frames does not
// weigh as much as a walk with hundreds (the per-clip average would let it).
TEST(FillMetrics, SummariesPoolFootSkatingOverContactFrames) {
  MOCAPFILL_REQUIRE_CORPUS();
  std::vector<ClipScore> scores;
  for (const char* name : {"dataset-1_walk_normal_001", "dataset-1_run_normal_001"}) {
    Result<Scene> scene = ImportFile(testing::DataPath(std::string("bandai-namco-1/data/") + name + ".bvh"));
    ASSERT_TRUE(scene.ok()) << scene.status().message();
    const MotionClip& truth = scene->clips[0];
    const MotionClip sketch = *MakeSketch(scene->skeleton, truth, LegSpec());
    Result<FillMetrics> m = ScoreFill(scene->skeleton, truth, sketch, sketch, *scene->skeleton.Find("Hips"));
    ASSERT_TRUE(m.ok());
    scores.push_back({name, "normal", "locomotion", "sketch", *m});
  }
  const FillMetrics& walk = scores[0].metrics;
  const FillMetrics& run = scores[1].metrics;
  ASSERT_GT(walk.foot_contact_frames, 10 * run.foot_contact_frames);  // the case the pooling is for
  const std::vector<SummaryRow> rows = Summarise(scores, {{"sketch", {}}});
  ASSERT_FALSE(rows.empty());
  const long frames = walk.foot_contact_frames + run.foot_contact_frames;
  EXPECT_EQ(rows[0].mean.foot_contact_frames, frames);
  EXPECT_NEAR(rows[0].mean.foot_skate_cm_per_s,
              (walk.foot_skate_cm_per_s * walk.foot_contact_frames + run.foot_skate_cm_per_s * run.foot_contact_frames) / frames,
              1e-9);
  EXPECT_GT(std::abs(rows[0].mean.foot_skate_cm_per_s - 0.5 * (walk.foot_skate_cm_per_s + run.foot_skate_cm_per_s)), 0.1);
  const long steps = walk.floor_steps + run.floor_steps;
  EXPECT_EQ(rows[0].mean.floor_steps, steps);
  const double glide_sum = walk.floor_glide_cm_per_s * walk.floor_steps + run.floor_glide_cm_per_s * run.floor_steps;
  EXPECT_NEAR(rows[0].mean.floor_glide_cm_per_s, glide_sum / steps, 1e-9);
}

// Floor glide: the capture's heels and toes roll and pivot on the floor at some centimetres a
// second; the sketch's legs, slerped between keys 8 frames apart under hips moving linearly,
// drag the feet along it several times as fast. The truth scored against itself glides as
// the capture does.
TEST(FillMetrics, FloorGlideMeasuresFeetDraggedAlongTheGround) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Scene walk = LoadWalk();
  const MotionClip& truth = walk.clips[0];
  const MotionClip sketch = *MakeSketch(walk.skeleton, truth, LegSpec());
  const int hips = *walk.skeleton.Find("Hips");
  Result<FillMetrics> self = ScoreFill(walk.skeleton, truth, sketch, truth, hips);
  Result<FillMetrics> slerped = ScoreFill(walk.skeleton, truth, sketch, sketch, hips);
  ASSERT_TRUE(self.ok() && slerped.ok());
  std::printf("floor glide, capture %.2f cm/s over %ld steps, sketch %.2f cm/s over %ld steps\n",
              self->capture_floor_glide_cm_per_s, self->capture_floor_steps, slerped->floor_glide_cm_per_s,
              slerped->floor_steps);
  EXPECT_DOUBLE_EQ(self->floor_glide_cm_per_s, self->capture_floor_glide_cm_per_s);
  EXPECT_EQ(self->floor_steps, self->capture_floor_steps);
  EXPECT_GT(self->capture_floor_steps, truth.num_frames);  // both feet stand about half the time
  EXPECT_GT(self->capture_floor_glide_cm_per_s, 1.0);
  EXPECT_LT(self->capture_floor_glide_cm_per_s, 20.0);
  EXPECT_GT(slerped->floor_glide_cm_per_s, 2.0 * slerped->capture_floor_glide_cm_per_s);
}

// Skating counts every contact frame of the capture; the slide is the part a foot moving no
// faster than a standing captured foot makes. The same walk a few frames late skates fast and
// hardly slides (its feet land after the capture's); dragged sideways it slides as fast as it
// is dragged.
TEST(FillMetrics, SlideSeparatesAFootDraggedFromAStepOutOfTime) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Scene walk = LoadWalk();
  const MotionClip& truth = walk.clips[0];
  const MotionClip sketch = *MakeSketch(walk.skeleton, truth, LegSpec());
  const int hips = *walk.skeleton.Find("Hips");
  MotionClip late = truth, dragged = truth;
  const int delay = 3;
  for (int f = 0; f < truth.num_frames; ++f)
    for (int j = 0; j < truth.num_joints; ++j) {
      late.rotation(f, j) = truth.rotation(std::max(0, f - delay), j);
      late.translation(f, j) = truth.translation(std::max(0, f - delay), j);
    }
  const double drag_m_per_s = 0.1;
  for (int f = 0; f < truth.num_frames; ++f) dragged.translation(f, hips).x() += drag_m_per_s * truth.time_s(f);
  Result<FillMetrics> self = ScoreFill(walk.skeleton, truth, sketch, truth, hips);
  Result<FillMetrics> lagging = ScoreFill(walk.skeleton, truth, sketch, late, hips);
  Result<FillMetrics> sliding = ScoreFill(walk.skeleton, truth, sketch, dragged, hips);
  ASSERT_TRUE(self.ok() && lagging.ok() && sliding.ok());
  std::printf("skate / slide cm/s: capture %.2f / %.2f, %d frames late %.2f / %.2f, dragged at 10 cm/s %.2f / %.2f\n",
              self->foot_skate_cm_per_s, self->foot_slide_cm_per_s, delay, lagging->foot_skate_cm_per_s,
              lagging->foot_slide_cm_per_s, sliding->foot_skate_cm_per_s, sliding->foot_slide_cm_per_s);
  EXPECT_DOUBLE_EQ(self->foot_slide_cm_per_s, self->foot_skate_cm_per_s);
  EXPECT_GT(lagging->foot_skate_cm_per_s, 10.0);  // 15.58
  EXPECT_LT(lagging->foot_slide_cm_per_s, 0.2 * lagging->foot_skate_cm_per_s);  // 2.21
  EXPECT_NEAR(sliding->foot_slide_cm_per_s, 100.0 * drag_m_per_s, 3.0);
  EXPECT_DOUBLE_EQ(sliding->foot_slide_cm_per_s, sliding->foot_skate_cm_per_s);
}

}  // namespace
}  // namespace mocapfill
