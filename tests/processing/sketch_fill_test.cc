// The fill use case on users' rigs and key times: the shipped sketch on the
// database's own rig, sketches keyed at 24 and 60 fps and at irregular times, a CMU sketch
// with texturing on, and translation keys that would stretch bones. Keys are checked at the
// animator's exact key times against the values the test wrote, not against the tool's own
// bookkeeping.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <map>

#include "formats/mfdb/mfdb_file.h"
#include "formats/motion_io.h"
#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "processing/database/motion_database_builder.h"
#include "processing/evaluation/sketch_maker.h"
#include "processing/motion/key_fidelity.h"
#include "processing/retargeting/retarget_scene.h"
#include "processing/sketch_fill/sketch_fill.h"
#include "processing/sketch_fill/sketch_keys.h"
#include "processing/synthesis/coverage.h"
#include "tests/support/bone_directions.h"
#include "tests/support/default_db.h"
#include "tests/support/sparse_sketch.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

namespace fs = std::filesystem;

constexpr double kKeyToleranceDeg = 0.01;  // keys below 0.01 degrees at their times

using testing::BandaiDbWithout;
using testing::DefaultDb;

const std::vector<std::string> kBandaiLegs = {"Hips",       "UpperLeg_L", "LowerLeg_L", "Foot_L", "Toes_L",
                                              "UpperLeg_R", "LowerLeg_R", "Foot_R",     "Toes_R"};

// Largest angle between the output at `times` and the source clip there, over `joints`.
double KeyErrorDeg(const Scene& out, const MotionClip& source, const Skeleton& source_skeleton,
                   const std::vector<std::string>& joints, const std::vector<double>& times) {
  double worst = 0.0;
  for (const std::string& name : joints) {
    const int o = *out.skeleton.Find(name), s = *source_skeleton.Find(name);
    for (double t : times)
      worst = std::max(worst, GeodesicAngle(SampleRotationAt(out.clips[0], o, t), SampleRotationAt(source, s, t)) * kDegPerRad);
  }
  return worst;
}

Result<SketchFillResult> FillFile(const std::string& path, SketchFillOptions options = {}) {
  ASSIGN_OR_RETURN(Scene sketch, ImportFile(path));
  return FillSketch(sketch, DefaultDb(), options);
}

// The motion of a file retargeted onto Geno (the shared corpus's character: Mixamo-style names,
// other proportions, an A-pose bind).
Result<Scene> OnGeno(const std::string& motion_path) {
  ASSIGN_OR_RETURN(const Scene motion, ImportFile(motion_path));
  ASSIGN_OR_RETURN(const Scene geno, ImportFile(testing::DataPath("geno/Geno.fbx")));
  return RetargetScene(motion, geno);
}

TEST(SketchFill, ShippedSketchOnTheDatabaseRig) {
  Result<SketchFillResult> r = FillFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_TRUE(r->rig.same_as_database);
  EXPECT_DOUBLE_EQ(r->output_rate_hz, 30.0);
  EXPECT_TRUE(r->uniform);
  EXPECT_LT(r->key_error_max_deg, kKeyToleranceDeg);
  EXPECT_GT(r->key_checks.size(), 8u);
  // The upper body is synthesised, not left at rest.
  int synthesized = 0;
  for (const JointFillInfo& j : r->joints) synthesized += j.kind == "synthesized";
  EXPECT_GE(synthesized, 10);
}

// A Bandai-Namco take whose header gives the hips another OFFSET than the database's first
// take, with end sites that a database read from a .mfdb (as `fill` reads its embedded one)
// lacks, is still the database's rig, so the fill copies its rotations exactly. The clip
// is part of the default database: its legs find their own take, and the synthesised hands
// and head come back as captured (a rig made anew from the BVH would aim the hands by its end
// sites, 35 degrees off the database's, and take the first frame as its rest).
TEST(SketchFill, DatabaseRigReadFromBvhIsTheDatabaseRig) {
  const std::string stored = testing::ScratchDir("sketch_db_rig") + "/default.mfdb";
  ASSERT_TRUE(WriteMfdb(DefaultDb(), stored).ok());
  Result<MotionDatabase> db = ReadMfdb(stored);
  ASSERT_TRUE(db.ok()) << db.status().message();
  Result<Scene> truth = ImportFile(testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"));
  ASSERT_TRUE(truth.ok()) << truth.status().message();
  // The header of the "tired" takes, whose hips OFFSET is their first position, 4.5 m from
  // the root (the database keeps the first take's, 0 93.92 -3 cm): the hips translate, so
  // their offset tells nothing of the rig.
  truth->skeleton.mutable_joint(*truth->skeleton.Find("Hips")).rest_translation = {0.00847027, 0.93984, -4.52225};
  SketchFillOptions options;
  options.keep = kBandaiLegs;
  Result<SketchFillResult> r = FillSketch(*truth, *db, options);
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_TRUE(r->rig.same_as_database);
  const MotionClip& out = r->scene.clips[0];
  double worst = 0.0, sum = 0.0;
  int count = 0;
  for (const char* name : {"Hand_L", "Hand_R", "Head"}) {
    const int j = *truth->skeleton.Find(name);
    for (int f = 0; f < out.num_frames; ++f) {
      const double e = GeodesicAngle(out.rotation(f, j), SampleRotationAt(truth->clips[0], j, out.time_s(f))) * kDegPerRad;
      worst = std::max(worst, e);
      sum += e;
      ++count;
    }
  }
  std::printf("synthesised hands and head against the capture: mean %.2f deg, worst %.2f deg\n", sum / count, worst);
  EXPECT_LT(sum / count, 5.0);
  EXPECT_LT(r->key_error_max_deg, kKeyToleranceDeg);
}

// Key times read from a glb are float32, whose spacing at 40 s (about 4e-6 s) exceeds a fixed
// 1e-6 s grid tolerance: such keys still lie on the sketch's 30 Hz grid, and the output is
// that uniform grid (with a fixed tolerance, two samples equal in float32 would make the
// writer refuse the file).
TEST(SketchFill, LongSketchKeysStayOnTheirGrid) {
  Result<Scene> source = ImportFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  ASSERT_TRUE(source.ok());
  std::vector<double> times;
  for (int k = 0; k * 8 <= 1200; ++k) times.push_back(static_cast<float>(k * 8 / 30.0));  // 40 s, as float32
  const std::string path = testing::ScratchDir("sketch_long") + "/sketch.gltf";
  ASSERT_TRUE(testing::WriteSparseSketch(source->skeleton, source->clips[0], kBandaiLegs, times, path));
  Result<SketchFillResult> r = FillFile(path);
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_TRUE(r->uniform);
  EXPECT_DOUBLE_EQ(r->output_rate_hz, 30.0);
  EXPECT_EQ(r->scene.clips[0].num_frames, 1201);
  EXPECT_LT(r->key_error_max_deg, kKeyToleranceDeg);
  const std::string out = testing::ScratchDir("sketch_long") + "/filled.glb";
  EXPECT_TRUE(ExportFile(r->scene, out).ok());
}

class SketchRates : public ::testing::TestWithParam<double> {};

// Keys every 8 frames of `fps` (24 or 60) or, for 0, at irregular times.
TEST_P(SketchRates, KeysExactAtTheirTimesAndOutputAtTheSketchRate) {
  const double fps = GetParam();
  Result<Scene> source = ImportFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  ASSERT_TRUE(source.ok());
  // The legs of the shipped sketch's capture-derived clip, resampled at the animator's keys.
  const MotionClip& clip = source->clips[0];
  // Every 8 frames at 24 fps, every 7 at 60 fps (every 8 would lie on the 30 Hz grid too,
  // and the lowest rate that holds every key time is the one detected).
  std::vector<double> times = fps > 0 ? testing::EveryStep(clip.duration_s(), (fps == 24 ? 8.0 : 7.0) / fps)
                                      : std::vector<double>{0.0, 0.313, 0.571, 0.937, 1.411, 1.623, 2.051, 2.507, 2.771,
                                                            3.303, 3.713, 4.181, 4.603, 5.053, 5.521, 6.103, 6.661, 7.201};
  const std::string path = testing::ScratchDir(std::string("sketch_rate_") + std::to_string(int(fps))) + "/sketch.gltf";
  ASSERT_TRUE(testing::WriteSparseSketch(source->skeleton, clip, kBandaiLegs, times, path));
  Result<SketchFillResult> r = FillFile(path);
  ASSERT_TRUE(r.ok()) << r.status().message();
  const MotionClip& out = r->scene.clips[0];
  if (fps > 0) {
    EXPECT_DOUBLE_EQ(r->output_rate_hz, fps);
    EXPECT_TRUE(r->uniform);
    EXPECT_EQ(out.num_frames, static_cast<int>(std::floor(times.back() * fps + 1e-6)) + 1);
  } else {
    EXPECT_FALSE(r->uniform);
    for (double t : times)  // every key time is a sample of the output
      EXPECT_TRUE(std::any_of(out.frame_times_s.begin(), out.frame_times_s.end(),
                              [t](double s) { return std::abs(s - t) < 1e-6; }))
          << t;
  }
  // Rotations within float32 rounding of the values written into the sketch.
  EXPECT_LT(KeyErrorDeg(r->scene, clip, source->skeleton, kBandaiLegs, times), kKeyToleranceDeg);
  EXPECT_LT(r->key_error_max_deg, kKeyToleranceDeg);
}

INSTANTIATE_TEST_SUITE_P(Rates, SketchRates, ::testing::Values(24.0, 60.0, 0.0));

TEST(SketchFill, OutputRateOnRequest) {
  SketchFillOptions options;
  options.output_rate_hz = 120.0;
  Result<SketchFillResult> r = FillFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"), options);
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_DOUBLE_EQ(r->output_rate_hz, 120.0);
  EXPECT_EQ(r->scene.clips[0].num_frames, 303 * 4 + 1);
  EXPECT_LT(r->key_error_max_deg, kKeyToleranceDeg);
}

// A CMU clip (another rig, 120 Hz) with hips and legs kept and texturing on: no joint flips
// between frames, and the keys hold.
TEST(SketchFill, CmuSketchWithTextureHasNoFlips) {
  SketchFillOptions options;
  options.keep = {"Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase", "RightUpLeg", "RightLeg", "RightFoot",
                  "RightToeBase"};
  options.fill.texture = true;
  Result<Scene> sketch = ImportFile(testing::FixturePath("bvh/cmu_01_01_short.bvh"));
  ASSERT_TRUE(sketch.ok());
  Result<SketchFillResult> r = FillSketch(*sketch, DefaultDb(), options);
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_FALSE(r->rig.same_as_database);
  EXPECT_DOUBLE_EQ(r->output_rate_hz, 120.0);
  EXPECT_LT(r->key_error_max_deg, kKeyToleranceDeg);
  EXPECT_LT(r->max_frame_jump_deg, 60.0);
}

TEST(SketchFill, CmuCorpusSketchHasNoFlips) {
  MOCAPFILL_REQUIRE_CORPUS();
  SketchFillOptions options;
  options.keep = {"Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase", "RightUpLeg", "RightLeg", "RightFoot",
                  "RightToeBase"};
  Result<Scene> sketch = ImportFile(testing::DataPath("cmu/01_01.bvh"));
  ASSERT_TRUE(sketch.ok());
  Result<SketchFillResult> r = FillSketch(*sketch, DefaultDb(), options);
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_LT(r->key_error_max_deg, kKeyToleranceDeg);
  // No joint turns by more than 60 degrees between two frames unless the capture itself does
  // (01_01 has a few such frames on the wrists and fingers).
  const std::vector<double> sketch_jumps = MaxFrameJumpsDeg(sketch->clips[0]);
  const std::vector<double> out_jumps = MaxFrameJumpsDeg(r->scene.clips[0]);
  for (int j = 0; j < sketch->skeleton.num_joints(); ++j)
    EXPECT_LT(out_jumps[j], std::max(60.0, sketch_jumps[j] + 1.0)) << sketch->skeleton.name(j);
}

TEST(SketchFill, TranslationKeysOnAFootAreRefused) {
  Result<Scene> source = ImportFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  ASSERT_TRUE(source.ok());
  Scene sketch = *source;
  MotionClip& clip = sketch.clips[0];
  const int foot = *sketch.skeleton.Find("Foot_L");
  for (int f = 0; f < clip.num_frames; ++f) clip.translation(f, foot) += Eigen::Vector3d(0.0, 0.3, 0.0);
  clip.translation_animated[foot] = 1;
  clip.keys[foot].translation_frames = clip.keys[foot].rotation_frames;
  Result<SketchFillResult> r = FillSketch(sketch, DefaultDb(), {});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), ErrorCode::kInvalidData);
  EXPECT_NE(r.status().message().find("Foot_L"), std::string::npos) << r.status().message();
  EXPECT_NE(r.status().message().find("--position-keys"), std::string::npos) << r.status().message();
}

}  // namespace
}  // namespace mocapfill

namespace mocapfill {
namespace {

// Mean upper-body direction error (degrees, in the hips' frame) of `filled` against `truth`,
// both on `rig`.
double UpperBodyErrorDeg(const Scene& rig_scene, const MotionClip& truth, const MotionClip& filled) {
  Result<PreparedRig> rig = PrepareRig(rig_scene);
  EXPECT_TRUE(rig.ok()) << rig.status().message();
  return testing::MeanDirectionErrorDeg(rig->rig, truth, rig->rig, filled, testing::UpperBodySegments());
}

// A sketch on the Geno character (hips and legs keyed every 8 frames, made by
// retargeting a Bandai-Namco clip onto Geno) filled against the Bandai-Namco database that
// lacks the clip's style, scored like the same clip filled on the Bandai rig: the upper body's
// bone-direction error within 15%.
TEST(SketchFill, GenoSketchScoresLikeTheBandaiRig) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<Scene> bandai = ImportFile(testing::DataPath("bandai-namco-1/data/dataset-1_walk_proud_002.bvh"));
  Result<Scene> geno = ImportFile(testing::DataPath("geno/Geno.fbx"));
  ASSERT_TRUE(bandai.ok() && geno.ok());
  Result<Scene> on_geno = RetargetScene(*bandai, *geno);
  ASSERT_TRUE(on_geno.ok()) << on_geno.status().message();
  const MotionDatabase& db = BandaiDbWithout("proud");

  struct Case {
    const Scene* scene;
    std::vector<std::string> legs;
    double error_deg = 0.0;
    Result<SketchFillResult> filled = InvalidArgument("not run");
  };
  Case cases[] = {{&*bandai, kBandaiLegs},
                  {&*on_geno,
                   {"Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase", "RightUpLeg", "RightLeg", "RightFoot",
                    "RightToeBase"}}};
  for (Case& c : cases) {
    SketchSpec spec;
    spec.keep_joints = c.legs;
    spec.key_every_frames = 8;
    Result<MotionClip> sketch_clip = MakeSketch(c.scene->skeleton, c.scene->clips[0], spec);
    ASSERT_TRUE(sketch_clip.ok()) << sketch_clip.status().message();
    Scene sketch = *c.scene;
    sketch.clips = {*sketch_clip};
    c.filled = FillSketch(sketch, db, {});
    ASSERT_TRUE(c.filled.ok()) << c.filled.status().message();
    EXPECT_LT(c.filled->key_error_max_deg, kKeyToleranceDeg);
    EXPECT_LT(c.filled->max_frame_jump_deg, 60.0);  // no flips on either rig
    c.error_deg = UpperBodyErrorDeg(*c.scene, c.scene->clips[0], c.filled->scene.clips[0]);
  }
  const double bandai_unexplained = MedianUnexplained(cases[0].filled->report.coverage);
  const double geno_unexplained = MedianUnexplained(cases[1].filled->report.coverage);
  std::printf("upper-body direction error (database without 'proud'): Bandai rig %.2f deg, Geno rig %.2f deg; "
              "median unexplained %.1f%% and %.1f%%\n",
              cases[0].error_deg, cases[1].error_deg, 100.0 * bandai_unexplained, 100.0 * geno_unexplained);
  EXPECT_LT(cases[1].error_deg, 1.15 * cases[0].error_deg);
  // The sketch reaches the database as well covered from Geno's rig as from the database's.
  EXPECT_LT(geno_unexplained, bandai_unexplained + 0.03);
  // The character comes back whole: Geno's mesh and skin, its 75 joints.
  const Scene& out = cases[1].filled->scene;
  EXPECT_EQ(out.skeleton.num_joints(), geno->skeleton.num_joints());
  EXPECT_EQ(out.meshes.size(), geno->meshes.size());
  EXPECT_EQ(out.skins.size(), geno->skins.size());
  EXPECT_FALSE(out.meshes.empty());
  ASSERT_TRUE(ExportFile(out, testing::TestOutputDir("fill") + "/geno_walk_proud_filled.glb").ok());
}

}  // namespace
}  // namespace mocapfill

namespace mocapfill {
namespace {

// A capture the database holds, retargeted onto another rig and sketched there (hips and legs
// every 8 frames), is found in the database as it is from the database's own rig: the
// retargeting onto the database's rig (its mean pose as rest) must not bend or twist the keyed
// legs by more than the matching tolerates. Shipped data only: the default database's walk on
// the Unreal (Quaternius) rig, and on the database's rig taken through the same retargeting
// (rest: the capture's mean pose) instead of copied.
TEST(SketchFill, CaptureOnAnotherRigIsCoveredAsOnTheDatabaseRig) {
  Result<Scene> walk = ImportFile(testing::FixturePath("default_db/dataset-1_walk_normal_001.bvh"));
  Result<Scene> unreal = ImportFile(testing::FixturePath("rigs/unreal_quaternius.bvh"));
  ASSERT_TRUE(walk.ok() && unreal.ok());
  Result<Scene> on_unreal = RetargetScene(*walk, *unreal);
  ASSERT_TRUE(on_unreal.ok()) << on_unreal.status().message();
  struct Case {
    const char* name;
    const Scene* scene;
    std::vector<std::string> legs;
    RestSource rest;
  };
  const Case cases[] = {
      {"database rig, copied", &*walk, kBandaiLegs, RestSource::kAuto},
      {"database rig, retargeted", &*walk, kBandaiLegs, RestSource::kMean},
      {"Unreal rig", &*on_unreal, {"pelvis", "thigh_l", "calf_l", "foot_l", "ball_l", "thigh_r", "calf_r", "foot_r",
                                   "ball_r"}, RestSource::kAuto}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    SketchSpec spec;
    spec.keep_joints = c.legs;
    Result<MotionClip> sketch_clip = MakeSketch(c.scene->skeleton, c.scene->clips[0], spec);
    ASSERT_TRUE(sketch_clip.ok()) << sketch_clip.status().message();
    Scene sketch = *c.scene;
    sketch.clips = {*sketch_clip};
    SketchFillOptions options;
    options.rest = c.rest;
    Result<SketchFillResult> r = FillSketch(sketch, DefaultDb(), options);
    ASSERT_TRUE(r.ok()) << r.status().message();
    const double unexplained = MedianUnexplained(r->report.coverage);
    std::printf("%s: median unexplained %.2f%%, %zu poorly covered stretches\n", c.name, 100.0 * unexplained,
                r->report.coverage.poor.size());
    EXPECT_LT(unexplained, 0.03);  // a walk the database holds; coverage calls 4% poor
    EXPECT_TRUE(r->report.coverage.poor.empty());
    EXPECT_LT(r->key_error_max_deg, kKeyToleranceDeg);
  }
}

// --position-keys: an animator who keyed the hips and placed the feet by translation keys (IK
// style) gets feet at those world positions, bones unstretched. `legs` are the leg joints
// (unkeyed and put at rest: the feet alone say where the legs go), `feet` the two foot joints.
void ExpectPositionKeysHeld(Scene sketch, const std::vector<std::string>& legs, const std::array<std::string, 2>& feet,
                            double tolerance_m) {
  MotionClip& clip = sketch.clips[0];
  const Skeleton& s = sketch.skeleton;
  // Where the keyed legs put the feet, at the keys.
  const std::vector<int> key_frames = clip.keys[*s.Find(feet[0])].rotation_frames;
  ASSERT_GE(key_frames.size(), 3u);
  std::vector<std::array<Eigen::Vector3d, 2>> targets;
  WorldPose pose;
  for (int f : key_frames) {
    ComputeWorldPose(s, clip, f, pose);
    targets.push_back({pose.positions[*s.Find(feet[0])], pose.positions[*s.Find(feet[1])]});
  }
  for (const std::string& leg : legs) {
    const int j = *s.Find(leg);
    clip.keys[j] = JointKeys{};
    for (int f = 0; f < clip.num_frames; ++f) clip.rotation(f, j) = s.joint(j).rest_rotation;
  }
  for (int side = 0; side < 2; ++side) {
    const int foot = *s.Find(feet[side]);
    for (size_t k = 0; k < key_frames.size(); ++k) {
      ComputeWorldPose(s, clip, key_frames[k], pose);
      const int shin = s.parent(foot);
      clip.translation(key_frames[k], foot) = pose.rotations[shin].conjugate() * (targets[k][side] - pose.positions[shin]);
    }
    clip.translation_animated[foot] = 1;
    clip.keys[foot].translation_frames = key_frames;
    clip.keys[foot].translation_times_s.clear();
    clip.keys[foot].translation_values.clear();
  }
  // Without --position-keys the keys would stretch the shins: refused.
  EXPECT_EQ(FillSketch(sketch, DefaultDb(), {}).status().code(), ErrorCode::kInvalidData);
  SketchFillOptions options;
  options.position_keys = {feet[0], feet[1]};
  options.fill.method = FillMethod::kHybrid;
  options.fill.pca.fit.full_pose = true;
  Result<SketchFillResult> r = FillSketch(sketch, DefaultDb(), options);
  ASSERT_TRUE(r.ok()) << r.status().message();
  // Measured here, on the output's own joints at the key frames, not taken from the report.
  const MotionClip& out = r->scene.clips[0];
  double worst = 0.0;
  for (size_t k = 0; k < key_frames.size(); ++k) {
    ComputeWorldPose(r->scene.skeleton, out, NearestFrame(out, clip.time_s(key_frames[k])), pose);
    for (int side = 0; side < 2; ++side)
      worst = std::max(worst, (pose.positions[*r->scene.skeleton.Find(feet[side])] - targets[k][side]).norm());
  }
  std::printf("position keys: max error %.3f cm (report: %.3f cm)\n", 100.0 * worst, 100.0 * r->position_key_error_max_m);
  ::testing::Test::RecordProperty("position_key_error_max_cm", std::to_string(100.0 * worst));
  EXPECT_LT(worst, tolerance_m);
  EXPECT_NEAR(r->position_key_error_max_m, worst, 1e-6);
  // Bones keep their lengths: the feet's offsets are their rest offsets.
  for (const std::string& name : feet) {
    const int foot = *s.Find(name);
    for (int f = 0; f < out.num_frames; ++f)
      ASSERT_LT((out.translation(f, foot) - s.joint(foot).rest_translation).norm(), 1e-9) << name;
  }
}

TEST(SketchFill, PositionKeysHoldTheFeet) {
  Result<Scene> source = ImportFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  ASSERT_TRUE(source.ok());
  ExpectPositionKeysHeld(*source, {"UpperLeg_L", "LowerLeg_L", "Foot_L", "Toes_L", "UpperLeg_R", "LowerLeg_R", "Foot_R", "Toes_R"},
                         {"Foot_L", "Foot_R"}, 0.01);
}

// On another rig (Geno: other proportions, an A-pose bind) the feet land as keyed too.
TEST(SketchFill, PositionKeysHoldTheFeetOnGeno) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<Scene> sketch = OnGeno(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  ASSERT_TRUE(sketch.ok()) << sketch.status().message();
  ExpectPositionKeysHeld(*sketch, {"LeftUpLeg", "LeftLeg", "LeftFoot", "LeftToeBase", "RightUpLeg", "RightLeg", "RightFoot", "RightToeBase"},
                         {"LeftFoot", "RightFoot"}, 0.01);
}

}  // namespace
}  // namespace mocapfill

namespace mocapfill {
namespace {

// The joints of the canonical hips, legs, feet and toes on a rig, by the rig's own names.
std::vector<std::string> LegJoints(const Scene& scene) {
  Result<PreparedRig> rig = PrepareRig(scene);
  EXPECT_TRUE(rig.ok()) << rig.status().message();
  std::vector<std::string> names;
  using B = HumanoidBone;
  for (B b : {B::kHips, B::kLeftUpperLeg, B::kLeftLowerLeg, B::kLeftFoot, B::kLeftToes, B::kRightUpperLeg,
              B::kRightLowerLeg, B::kRightFoot, B::kRightToes})
    if (rig.ok() && rig->mapping.has(b)) names.push_back(scene.skeleton.name(rig->mapping.joint(b)));
  return names;
}

// Every real rig here, keyed at hips and legs and filled with texturing on: keys exact at
// their times, and no joint turns by more than 60 degrees between output frames unless the
// sketch itself does.
TEST(SketchFill, EveryRigKeepsKeysWithoutFlips) {
  std::vector<std::string> files = {"bvh/bandai_walk_normal_001_short.bvh", "bvh/cmu_01_01_short.bvh",
                                    "bvh/boxing_toes_short.bvh", "rigs/mixamo_prefixed.bvh", "rigs/rigify_def.bvh",
                                    "rigs/smpl_body.bvh", "rigs/unreal_quaternius.bvh"};
  for (std::string& f : files) f = testing::FixturePath(f);
  if (!testing::DataDir().empty())
    for (const char* f : {"assimp/Boxing_Toes.bvh", "geno/Geno_bind.bvh", "geno/Geno_stance.bvh", "cmu/01_03.bvh"})
      files.push_back(testing::DataPath(f));
  else
    std::printf("shared corpus not found (../shared/data): its rigs skipped\n");
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    Result<Scene> sketch = ImportFile(file);
    ASSERT_TRUE(sketch.ok()) << sketch.status().message();
    SketchFillOptions options;
    options.keep = LegJoints(*sketch);
    ASSERT_GE(options.keep.size(), 7u);
    Result<SketchFillResult> r = FillSketch(*sketch, DefaultDb(), options);
    ASSERT_TRUE(r.ok()) << r.status().message();
    EXPECT_LT(r->key_error_max_deg, kKeyToleranceDeg);
    const std::vector<double> sketch_jumps = MaxFrameJumpsDeg(sketch->clips[0]);
    const std::vector<double> out_jumps = MaxFrameJumpsDeg(r->scene.clips[0]);
    for (int j = 0; j < sketch->skeleton.num_joints(); ++j)
      EXPECT_LT(out_jumps[j], std::max(60.0, sketch_jumps[j] + 1.0)) << sketch->skeleton.name(j);
  }
}

// On the user's own rig: Geno (Mixamo-style names, 75 joints) walking with only the hips, torso,
// head and arms keyed every 8 frames. The legs are synthesised on the database's rig, their
// feet's contacts voted from the matched takes, and carried back onto Geno's legs and its own
// frame times, where the planter holds them: the held feet stand, the keys stay exact.
TEST(SketchFill, GenoSynthesisedFeetStandOnTheTakesContacts) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<Scene> on_geno = OnGeno(testing::DataPath("bandai-namco-1/data/dataset-1_walk_proud_001.bvh"));
  ASSERT_TRUE(on_geno.ok()) << on_geno.status().message();
  const Skeleton& s = on_geno->skeleton;
  SketchSpec spec;
  for (int j = 0; j < s.num_joints(); ++j) {
    const std::string& name = s.name(j);
    if (name.find("Leg") == std::string::npos && name.find("Foot") == std::string::npos &&
        name.find("Toe") == std::string::npos)
      spec.keep_joints.push_back(name);
  }
  Result<MotionClip> clip = MakeSketch(s, on_geno->clips[0], spec);
  ASSERT_TRUE(clip.ok()) << clip.status().message();
  Scene sketch = *on_geno;
  sketch.clips = {*clip};
  Result<SketchFillResult> filled = FillSketch(sketch, BandaiDbWithout("proud"), {});
  ASSERT_TRUE(filled.ok()) << filled.status().message();
  EXPECT_LT(filled->key_error_max_deg, kKeyToleranceDeg);
  const MotionClip& out = filled->scene.clips[0];
  double slide = 0.0;
  int frames = 0, from_takes = 0;
  WorldPose pose;
  for (const FootContact& c : filled->feet.contacts) {
    if (c.found_on != "takes") continue;
    ++from_takes;
    if (c.part != "heel") continue;
    const int foot = *s.Find(c.side == "left" ? "LeftFoot" : "RightFoot");
    Eigen::Vector3d before = Eigen::Vector3d::Zero();
    for (int f = NearestFrame(out, c.start_s); f <= NearestFrame(out, c.end_s); ++f) {
      ComputeWorldPose(s, out, f, pose);
      if (f > NearestFrame(out, c.start_s)) {
        const Eigen::Vector3d step = (pose.positions[foot] - before) / (out.time_s(f) - out.time_s(f - 1));
        slide += std::hypot(step.x(), step.z());
        ++frames;
      }
      before = pose.positions[foot];
    }
  }
  std::printf("Geno, legs synthesised: %d contacts from the takes, heels sliding %.2f cm/s over %d frames\n",
              from_takes, 100.0 * slide / std::max(1, frames), frames);
  EXPECT_GT(from_takes, 10);
  ASSERT_GT(frames, 50);
  EXPECT_LT(slide / frames, 0.02);
}

}  // namespace
}  // namespace mocapfill
