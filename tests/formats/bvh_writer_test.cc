// BVH export: BVH -> Scene -> text -> Scene keeps joints, channel layouts and motion on
// every fixture; non-BVH scenes get the default layout with rest rotations and scales
// folded in; Euler curves stay continuous; units and Frame Time read back the same.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

#include "formats/bvh/bvh_reader.h"
#include "formats/bvh/bvh_writer.h"
#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "tests/formats/bvh_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::FixturePath;
using testing::kRoundTripRotationToleranceDeg;
using testing::kRoundTripTranslationToleranceM;
using testing::ReadFixture;
using testing::ReadText;

// Writes `scene` and reads the text back (same unit choice as the source unless given).
Result<Scene> RoundTrip(const Scene& scene, std::string* text_out = nullptr, ImportOptions read_options = {},
                        const ExportOptions& write_options = {}) {
  Result<std::string> text = WriteBvh(scene, write_options);
  if (!text.ok()) return text.status();
  if (text_out) *text_out = *text;
  return ReadBvh(*text, "roundtrip.bvh", read_options);
}

double WorstWorldDistanceM(const Scene& a, const Scene& b) {
  const auto pa = ComputeWorldPositions(a.skeleton, a.clips[0]);
  double worst = 0.0;
  const auto pb = ComputeWorldPositions(b.skeleton, b.clips[0]);
  for (int j = 0; j < a.skeleton.num_joints(); ++j) {
    const int k = *b.skeleton.Find(a.skeleton.name(j));
    for (int f = 0; f < a.clips[0].num_frames; ++f)
      worst = std::max(worst, (pa[f * a.skeleton.num_joints() + j] - pb[f * b.skeleton.num_joints() + k]).norm());
  }
  return worst;
}

class BvhFixtureRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST_P(BvhFixtureRoundTrip, KeepsJointsLayoutAndMotion) {
  const Result<Scene> source = ReadFixture(GetParam());
  ASSERT_TRUE(source.ok()) << source.status().message();
  std::string text;
  const Result<Scene> back = RoundTrip(*source, &text);
  ASSERT_TRUE(back.ok()) << back.status().message();
  testing::ExpectSameSkeleton(source->skeleton, back->skeleton, kRoundTripTranslationToleranceM);
  EXPECT_EQ(back->clips[0].sample_rate_hz, source->clips[0].sample_rate_hz);
  EXPECT_EQ(back->clips[0].num_frames, source->clips[0].num_frames);
  EXPECT_EQ(back->source.unit_name, source->source.unit_name);
  EXPECT_EQ(back->clips[0].translation_animated, source->clips[0].translation_animated);
  const testing::MotionDifference d = testing::CompareMotion(*source, *back);
  EXPECT_LT(d.rotation_deg, kRoundTripRotationToleranceDeg);
  EXPECT_LT(d.translation_m, kRoundTripTranslationToleranceM);
  EXPECT_LT(testing::MaxRotationChannelJumpDeg(text), 180.0);
  EXPECT_TRUE(back->warnings.empty());  // Frames now matches the rows
}

INSTANTIATE_TEST_SUITE_P(Fixtures, BvhFixtureRoundTrip,
                         ::testing::Values("cmu_01_01_short.bvh", "bandai_walk_normal_001_short.bvh",
                                           "boxing_toes_short.bvh", "cmu_crlf.bvh", "cmu_mixed_orders.bvh",
                                           "cmu_two_roots.bvh", "bandai_names.bvh", "boxing_interleaved.bvh"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           return param.param.substr(0, param.param.find('.'));
                         });

// The standard layout (--bvh-layout standard): three rotations on every joint; positions only
// on joints that move, over a zero OFFSET, so that a reader adding position channels to the
// OFFSET (three.js) and one replacing it (ours) read the same motion. Bandai-Namco's files
// carry positions on all 22 joints; only Hips moves (joint_Root above it is static).
// Each joint's OFFSET and CHANNELS as written, by name (End Sites left out).
struct WrittenJoint {
  Eigen::Vector3d offset = Eigen::Vector3d::Constant(NAN);
  std::vector<std::string> channels;
};
std::map<std::string, WrittenJoint> WrittenJoints(const std::string& text) {
  std::map<std::string, WrittenJoint> joints;
  std::istringstream in(text.substr(0, text.find("MOTION")));
  std::string line;
  WrittenJoint* current = nullptr;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string keyword;
    words >> keyword;
    if (keyword == "ROOT" || keyword == "JOINT") {
      std::string name;
      words >> name;
      current = &joints[name];
    } else if (keyword == "End") {
      current = nullptr;
    } else if (keyword == "OFFSET" && current != nullptr) {
      words >> current->offset.x() >> current->offset.y() >> current->offset.z();
    } else if (keyword == "CHANNELS" && current != nullptr) {
      int count = 0;
      words >> count;
      current->channels.resize(count);
      for (std::string& c : current->channels) words >> c;
    }
  }
  return joints;
}

class BvhStandardLayout : public ::testing::TestWithParam<std::string> {};

TEST_P(BvhStandardLayout, PositionsOnlyOnMovingJointsOverZeroOffsets) {
  const Result<Scene> source = ReadFixture(GetParam());
  ASSERT_TRUE(source.ok()) << source.status().message();
  ExportOptions standard;
  standard.bvh_layout = BvhLayout::kStandard;
  std::string text;
  const Result<Scene> back = RoundTrip(*source, &text, {}, standard);
  ASSERT_TRUE(back.ok()) << back.status().message();
  const MotionClip& clip = source->clips[0];
  const std::map<std::string, WrittenJoint> written = WrittenJoints(text);
  ASSERT_EQ(written.size(), static_cast<size_t>(source->skeleton.num_joints()));
  int moving = 0;
  for (int j = 0; j < source->skeleton.num_joints(); ++j) {
    const std::string& name = source->skeleton.name(j);
    bool moves = false;
    for (int f = 1; f < clip.num_frames; ++f) moves = moves || clip.translation(f, j) != clip.translation(0, j);
    ASSERT_TRUE(written.count(name)) << name;
    const WrittenJoint& w = written.at(name);
    ASSERT_EQ(w.channels.size(), moves ? 6u : 3u) << name;
    for (size_t k = 0; k < w.channels.size(); ++k)
      EXPECT_NE(w.channels[k].find(k + 3 < w.channels.size() ? "position" : "rotation"), std::string::npos)
          << name << " " << w.channels[k];
    if (moves) {
      EXPECT_EQ(w.offset, Eigen::Vector3d::Zero()) << name;
      ++moving;
    }
  }
  EXPECT_GT(moving, 0);
  EXPECT_LT(WorstWorldDistanceM(*source, *back), 1e-9);
  const testing::MotionDifference d = testing::CompareMotion(*source, *back);
  EXPECT_LT(d.rotation_deg, kRoundTripRotationToleranceDeg);
}

INSTANTIATE_TEST_SUITE_P(Fixtures, BvhStandardLayout,
                         ::testing::Values("cmu_01_01_short.bvh", "bandai_walk_normal_001_short.bvh",
                                           "boxing_toes_short.bvh", "cmu_mixed_orders.bvh", "cmu_two_roots.bvh",
                                           "boxing_interleaved.bvh"),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           return param.param.substr(0, param.param.find('.'));
                         });

TEST(BvhStandardLayout, BandaiNamcoKeepsPositionsOnHipsAlone) {
  const Result<Scene> source = ReadFixture("bandai_walk_normal_001_short.bvh");
  ASSERT_TRUE(source.ok());
  ExportOptions standard;
  standard.bvh_layout = BvhLayout::kStandard;
  const Result<std::string> text = WriteBvh(*source, standard);
  ASSERT_TRUE(text.ok());
  EXPECT_NE(text->find("ROOT joint_Root\n{\n\tOFFSET"), std::string::npos);
  EXPECT_NE(text->find("JOINT Hips\n\t{\n\t\tOFFSET 0 0 0\n\t\tCHANNELS 6 Xposition Yposition Zposition"),
            std::string::npos)
      << text->substr(0, 400);
  size_t six = 0;
  for (size_t at = text->find("CHANNELS 6"); at != std::string::npos; at = text->find("CHANNELS 6", at + 1)) ++six;
  EXPECT_EQ(six, 1u);
}

TEST(BvhWriter, WritesTheSourceNumbersBack) {
  // cmu_01_01_short keeps its principal-branch angles, so every value comes back as written,
  // as do the OFFSETs of Bandai's constant position channels and the Frame Time text.
  for (const char* name : {"cmu_01_01_short.bvh", "boxing_toes_short.bvh"}) {
    const std::string original = ReadText(FixturePath(std::string("bvh/") + name));
    const Result<Scene> scene = ReadFixture(name);
    ASSERT_TRUE(scene.ok());
    const Result<std::string> text = WriteBvh(*scene, {});
    ASSERT_TRUE(text.ok());
    const auto rows_in = testing::MotionRows(original);
    const auto rows_out = testing::MotionRows(*text);
    ASSERT_EQ(rows_out.size(), static_cast<size_t>(scene->clips[0].num_frames));
    for (size_t f = 0; f < rows_out.size(); ++f) EXPECT_EQ(rows_out[f], rows_in[f]) << name << " frame " << f;
  }
  const Result<Scene> bandai = ReadFixture("bandai_walk_normal_001_short.bvh");
  ASSERT_TRUE(bandai.ok());
  const std::string text = *WriteBvh(*bandai, {});
  EXPECT_NE(text.find("\t\tJOINT Spine\n\t\t{\n\t\t\tOFFSET 15.7357 0 0\n"), std::string::npos);
  EXPECT_NE(text.find("Frame Time: 0.0333333\n"), std::string::npos);
  EXPECT_NE(text.find("\t\t\t\t\t\tEnd Site\n\t\t\t\t\t\t{\n\t\t\t\t\t\t\tOFFSET 0 0 0\n"), std::string::npos);
}

// A scene as a glTF import would give it: no BVH layout, metres, non-identity rest rotations
// (clip rotations are the full local rotations), a scaled joint, and a leaf without End Site.
Scene GltfLikeScene() {
  Scene scene = *ReadFixture("cmu_01_01_short.bvh");
  scene.source = SourceInfo{};
  scene.source.format = "gltf";
  for (int j = 0; j < scene.skeleton.num_joints(); ++j) {
    Joint& joint = scene.skeleton.mutable_joint(j);
    joint.bvh_channels.clear();
    joint.rest_rotation = EulerDegreesToQuaternion({10.0 * j, 5, -20}, *EulerOrder::Parse("XYZ"));
  }
  scene.skeleton.mutable_joint(*scene.skeleton.Find("LeftUpLeg")).rest_scale = Eigen::Vector3d(1.5, 1.5, 1.5);
  scene.skeleton.mutable_joint(*scene.skeleton.Find("Head")).end_site.reset();
  return scene;
}

TEST(BvhWriter, NonBvhScenesGetTheDefaultLayoutWithRestFoldedIn) {
  const Scene scene = GltfLikeScene();
  std::string text;
  ImportOptions metres;
  metres.unit = "m";
  const Result<Scene> back = RoundTrip(scene, &text, metres);
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_EQ(back->skeleton.joint(0).bvh_channels,
            (std::vector<std::string>{"Xposition", "Yposition", "Zposition", "Zrotation", "Xrotation", "Yrotation"}));
  EXPECT_EQ(back->skeleton.joint(1).bvh_channels, (std::vector<std::string>{"Zrotation", "Xrotation", "Yrotation"}));
  // BVH has no rest rotation: the rotation written is the whole local rotation.
  const testing::MotionDifference d = testing::CompareMotion(scene, *back);
  EXPECT_LT(d.rotation_deg, kRoundTripRotationToleranceDeg);
  // LeftUpLeg's scale of 1.5 lengthens its children's offsets; world positions agree.
  EXPECT_LT(WorstWorldDistanceM(scene, *back), kRoundTripTranslationToleranceM);
  const Joint& head = back->skeleton.joint(*back->skeleton.Find("Head"));
  ASSERT_TRUE(head.end_site.has_value());  // zero-length End Site keeps the file valid
  EXPECT_EQ(*head.end_site, Eigen::Vector3d::Zero());
  EXPECT_LT(testing::MaxRotationChannelJumpDeg(text), 180.0);
}

TEST(BvhWriter, WidensALayoutWhenTheMotionNeedsMoreChannels) {
  Scene scene = *ReadFixture("boxing_toes_short.bvh");
  MotionClip& clip = scene.clips[0];
  const int ab = *scene.skeleton.Find("Ab");
  for (int f = 0; f < clip.num_frames; ++f) clip.translation(f, ab).y() += 0.001 * f;  // Ab now stretches
  clip.DetectAnimatedTranslations();
  // Head keeps only Zrotation in its layout, but turns about X too.
  const int head = *scene.skeleton.Find("Head");
  scene.skeleton.mutable_joint(head).bvh_channels = {"Zrotation"};
  for (int f = 0; f < clip.num_frames; ++f) clip.rotation(f, head) = EulerDegreesToQuaternion({f * 1.0, 30, 0}, *EulerOrder::Parse("ZXY"));
  const Result<Scene> back = RoundTrip(scene);
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_EQ(back->skeleton.joint(ab).bvh_channels,
            (std::vector<std::string>{"Xposition", "Yposition", "Zposition", "Zrotation", "Xrotation", "Yrotation"}));
  EXPECT_EQ(back->skeleton.joint(head).bvh_channels, (std::vector<std::string>{"Zrotation", "Xrotation", "Yrotation"}));
  const testing::MotionDifference d = testing::CompareMotion(scene, *back);
  EXPECT_LT(d.rotation_deg, kRoundTripRotationToleranceDeg);
  EXPECT_LT(d.translation_m, kRoundTripTranslationToleranceM);

  // A joint that only turns about Z keeps its one-channel layout.
  for (int f = 0; f < clip.num_frames; ++f) clip.rotation(f, head) = EulerDegreesToQuaternion({f * 1.0, 0, 0}, *EulerOrder::Parse("ZXY"));
  const Result<Scene> narrow = RoundTrip(scene);
  ASSERT_TRUE(narrow.ok()) << narrow.status().message();
  EXPECT_EQ(narrow->skeleton.joint(head).bvh_channels, std::vector<std::string>{"Zrotation"});
  EXPECT_LT(testing::CompareMotion(scene, *narrow).rotation_deg, kRoundTripRotationToleranceDeg);
}

TEST(BvhWriter, EulerCurvesStayContinuousThroughFullTurnsAndGimbalLock) {
  Scene scene = *ReadFixture("boxing_toes_short.bvh");
  MotionClip& clip = scene.clips[0];
  const EulerOrder zxy = *EulerOrder::Parse("ZXY");
  for (int f = 0; f < clip.num_frames; ++f) {
    clip.rotation(f, 0) = EulerDegreesToQuaternion({0, 0, 9.0 * f}, zxy);          // 720 degrees about Y
    clip.rotation(f, 1) = EulerDegreesToQuaternion({20, 60 + 1.0 * f, 10}, zxy);   // X passes 90: gimbal lock
    clip.rotation(f, 2) = EulerDegreesToQuaternion({170 + 2.0 * f, -5, 3}, zxy);   // Z passes 180
  }
  clip.MakeContinuous();
  std::string text;
  const Result<Scene> back = RoundTrip(scene, &text);
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_LT(testing::MaxRotationChannelJumpDeg(text), 10.0);
  EXPECT_LT(testing::CompareMotion(scene, *back).rotation_deg, kRoundTripRotationToleranceDeg);
  const auto rows = testing::MotionRows(text);
  EXPECT_NEAR(rows.back()[5], 9.0 * 79, 1e-6);  // Hips' Yrotation keeps counting past 360
}

TEST(BvhWriter, UnitsAndFrameTime) {
  const Scene scene = *ReadFixture("cmu_01_01_short.bvh");
  ExportOptions metres;
  metres.unit = "m";
  ImportOptions read_metres;
  read_metres.unit = "m";
  std::string text;
  const Result<Scene> back = RoundTrip(scene, &text, read_metres, metres);
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_LT(testing::CompareMotion(scene, *back).translation_m, kRoundTripTranslationToleranceM);
  EXPECT_NEAR(testing::MotionRows(text)[0][1], 17.8693 * 0.056444, 1e-12);
  EXPECT_NE(text.find("Frame Time: .0083333\n"), std::string::npos);

  ExportOptions bad;
  bad.unit = "furlong";
  EXPECT_EQ(WriteBvh(scene, bad).status().code(), ErrorCode::kInvalidArgument);

  Scene ntsc = scene;
  ntsc.source.source_frame_time_text.clear();
  ntsc.clips[0].sample_rate_hz = 30000.0 / 1001;
  const Result<std::string> ntsc_text = WriteBvh(ntsc, {});
  ASSERT_TRUE(ntsc_text.ok());
  EXPECT_NE(ntsc_text->find("Frame Time: 0.0333666667\n"), std::string::npos);
  EXPECT_EQ(ReadBvh(*ntsc_text, "ntsc.bvh", {})->clips[0].sample_rate_hz, 30000.0 / 1001);
  // A source Frame Time that no longer matches the clip's rate is not reused.
  Scene resampled = scene;
  resampled.clips[0].sample_rate_hz = 30.0;
  EXPECT_NE(WriteBvh(resampled, {})->find("Frame Time: 0.0333333333\n"), std::string::npos);
}

TEST(BvhWriter, FirstClipOnlyRestPoseWithoutClipsAndDeterministicText) {
  Scene scene = *ReadFixture("boxing_toes_short.bvh");
  Scene two = scene;
  MotionClip second = two.clips[0];
  second.num_frames = 3;
  second.rotations.resize(3 * second.num_joints);
  second.translations.resize(3 * second.num_joints);
  two.clips.push_back(second);
  const Result<std::string> first_only = WriteBvh(two, {});
  ASSERT_TRUE(first_only.ok());
  EXPECT_EQ(*first_only, *WriteBvh(scene, {}));
  EXPECT_NE(first_only->find("Frames: 80\n"), std::string::npos);

  Scene still = scene;
  still.clips.clear();
  const Result<Scene> rest = RoundTrip(still);
  ASSERT_TRUE(rest.ok()) << rest.status().message();
  EXPECT_EQ(rest->clips[0].num_frames, 1);
  EXPECT_EQ(rest->clips[0].sample_rate_hz, 30.0);
  EXPECT_LT((rest->clips[0].translation(0, 3) - scene.skeleton.joint(3).rest_translation).norm(), 1e-12);
}

TEST(BvhWriter, RejectsNamesBvhCannotHold) {
  Scene scene = *ReadFixture("boxing_toes_short.bvh");
  scene.skeleton.mutable_joint(2).name = "Chest\nJOINT Fake";
  const Result<std::string> text = WriteBvh(scene, {});
  ASSERT_FALSE(text.ok());
  EXPECT_EQ(text.status().code(), ErrorCode::kInvalidData);
  EXPECT_NE(text.status().message().find("line break"), std::string::npos);
}

}  // namespace
}  // namespace mocapfill
