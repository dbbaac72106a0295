// BVH import on real captures (short cuts of CMU 01_01, Bandai-Namco walk, Assimp
// Boxing_Toes) and on variants of them for corner cases: every number the importer
// produces is checked against the raw text of the file.
#include <gtest/gtest.h>

#include <cmath>

#include "formats/bvh/bvh_reader.h"
#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "tests/formats/bvh_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::FixturePath;
using testing::kExactM;
using testing::ReadFixture;
using testing::ReadText;

constexpr double kSnappedM = 1e-9;           // metres: constant channels snapped to frame 0
constexpr double kRotationTolDeg = 1e-9;     // same Euler numbers, two composition codes
constexpr double kCmuUnitM = 0.056444;

// Every joint at `frame` against the raw row: rotations composed from the listed angles,
// listed position components scaled to metres.
void ExpectFrameMatchesText(const Scene& scene, const std::string& text, int frame, double unit_m) {
  const auto rows = testing::MotionRows(text);
  const auto channels = testing::ChannelLines(text);
  ASSERT_EQ(static_cast<int>(channels.size()), scene.skeleton.num_joints());
  const MotionClip& clip = scene.clips.at(0);
  size_t column = 0;
  for (int j = 0; j < scene.skeleton.num_joints(); ++j) {
    const double* values = rows.at(frame).data() + column;
    const Eigen::Quaterniond expected = testing::RotationFromChannels(channels[j], values);
    EXPECT_LT(GeodesicAngle(clip.rotation(frame, j), expected) * kDegPerRad, kRotationTolDeg)
        << scene.skeleton.name(j) << " frame " << frame;
    for (size_t c = 0; c < channels[j].size(); ++c) {
      if (channels[j][c].find("position") == std::string::npos) continue;
      EXPECT_NEAR(clip.translation(frame, j)[channels[j][c][0] - 'X'], values[c] * unit_m, kSnappedM)
          << scene.skeleton.name(j) << " " << channels[j][c] << " frame " << frame;
    }
    column += channels[j].size();
  }
}

std::vector<std::string> AnimatedJoints(const Scene& scene) {
  std::vector<std::string> names;
  for (int j = 0; j < scene.skeleton.num_joints(); ++j)
    if (scene.clips[0].translation_animated[j]) names.push_back(scene.skeleton.name(j));
  return names;
}

TEST(BvhReader, CmuClipMatchesTheRawText) {
  const Result<Scene> scene = ReadFixture("cmu_01_01_short.bvh");
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const MotionClip& clip = scene->clips.at(0);
  EXPECT_EQ(scene->skeleton.num_joints(), 31);
  EXPECT_EQ(clip.num_frames, 60);
  EXPECT_EQ(clip.sample_rate_hz, 120.0);
  EXPECT_EQ(clip.name, "cmu_01_01_short");
  EXPECT_EQ(scene->source.format, "bvh");
  EXPECT_EQ(scene->source.source_frame_time_text, ".0083333");
  EXPECT_EQ(scene->source.source_frame_time_s, 0.0083333);
  EXPECT_EQ(scene->source.declared_frames, 60);
  // Hips stand ~17.9 units high: centimetres would make a 0.3 m figure, so the CMU unit is detected.
  EXPECT_EQ(scene->source.unit_name, "cmu");
  EXPECT_TRUE(scene->source.unit_detected);
  EXPECT_EQ(scene->source.unit_scale_to_m, kCmuUnitM);
  EXPECT_TRUE(scene->warnings.empty());
  // First row: "9.3722 17.8693 -17.3198 0 0 0 ..."
  EXPECT_NEAR(clip.translation(0, 0).x(), 9.3722 * kCmuUnitM, kExactM);
  EXPECT_NEAR(clip.translation(0, 0).y(), 17.8693 * kCmuUnitM, kExactM);
  EXPECT_NEAR(clip.translation(0, 0).z(), -17.3198 * kCmuUnitM, kExactM);
  const std::string text = ReadText(FixturePath("bvh/cmu_01_01_short.bvh"));
  for (int frame : {0, 1, 30, 59}) ExpectFrameMatchesText(*scene, text, frame, kCmuUnitM);
  EXPECT_EQ(AnimatedJoints(*scene), std::vector<std::string>{"Hips"});
  // LeftToeBase's End Site: "OFFSET 0.00000 -0.00000 1.18966".
  const int toe = *scene->skeleton.Find("LeftToeBase");
  ASSERT_TRUE(scene->skeleton.joint(toe).end_site.has_value());
  EXPECT_NEAR(scene->skeleton.joint(toe).end_site->z(), 1.18966 * kCmuUnitM, kExactM);
  EXPECT_EQ(scene->skeleton.joint(0).bvh_channels,
            (std::vector<std::string>{"Xposition", "Yposition", "Zposition", "Zrotation", "Yrotation", "Xrotation"}));
  EXPECT_EQ(clip.keys.at(5).rotation_frames.size(), 60u);
  EXPECT_EQ(clip.keys.at(0).translation_frames.size(), 60u);
  EXPECT_TRUE(clip.keys.at(5).translation_frames.empty());
  EXPECT_TRUE(clip.Validate(scene->skeleton).ok());
  for (int f = 1; f < clip.num_frames; ++f)
    for (int j = 0; j < clip.num_joints; ++j)
      EXPECT_GE(clip.rotation(f, j).coeffs().dot(clip.rotation(f - 1, j).coeffs()), 0.0) << "hemisphere jump";
}

TEST(BvhReader, BandaiWalkKeepsOnlyHipsTranslationAnimated) {
  const Result<Scene> scene = ReadFixture("bandai_walk_normal_001_short.bvh");
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const MotionClip& clip = scene->clips.at(0);
  EXPECT_EQ(scene->skeleton.num_joints(), 22);
  EXPECT_EQ(clip.num_frames, 40);
  EXPECT_EQ(clip.sample_rate_hz, 30.0);
  EXPECT_EQ(scene->source.source_frame_time_text, "0.0333333");
  EXPECT_EQ(scene->source.unit_name, "cm");
  EXPECT_FALSE(scene->source.unit_detected);
  // Every joint declares six channels, but only Hips moves (joint_Root stays at the origin).
  EXPECT_EQ(AnimatedJoints(*scene), std::vector<std::string>{"Hips"});
  EXPECT_NEAR(clip.translation(0, 1).x(), -0.0171443, kExactM);
  EXPECT_NEAR(clip.translation(0, 1).y(), 0.902704, kExactM);
  EXPECT_NEAR(clip.translation(0, 1).z(), -4.07123, kExactM);
  // Spine's position channels hold "15.7357 5.1072e-06 -5.51764e-07" on every frame while
  // its OFFSET says "15.7357 0 0": the rest pose takes the value in use, the OFFSET is kept.
  const Joint& spine = scene->skeleton.joint(*scene->skeleton.Find("Spine"));
  EXPECT_NEAR(spine.rest_translation.y(), 5.1072e-08, kExactM);
  ASSERT_TRUE(spine.bvh_offset.has_value());
  EXPECT_EQ(spine.bvh_offset->y(), 0.0);
  EXPECT_NEAR(spine.bvh_offset->x(), 0.157357, kExactM);
  const int spine_index = *scene->skeleton.Find("Spine");
  for (int f = 0; f < clip.num_frames; ++f) EXPECT_EQ(clip.translation(f, spine_index), spine.rest_translation);
  EXPECT_FALSE(scene->skeleton.joint(0).bvh_offset.has_value());  // joint_Root: channels equal its OFFSET
  const std::string text = ReadText(FixturePath("bvh/bandai_walk_normal_001_short.bvh"));
  for (int frame : {0, 17, 39}) ExpectFrameMatchesText(*scene, text, frame, 0.01);
  const Joint& head = scene->skeleton.joint(*scene->skeleton.Find("Head"));
  ASSERT_TRUE(head.end_site.has_value());
  EXPECT_EQ(*head.end_site, Eigen::Vector3d::Zero());
}

TEST(BvhReader, BoxingToesWarnsAboutTheFrameCountAndStrictFails) {
  const Result<Scene> scene = ReadFixture("boxing_toes_short.bvh");
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->skeleton.num_joints(), 21);
  EXPECT_EQ(scene->clips[0].num_frames, 80);  // the rows present win
  EXPECT_EQ(scene->clips[0].sample_rate_hz, 100.0);
  EXPECT_EQ(scene->source.declared_frames, 79);
  ASSERT_EQ(scene->warnings.size(), 1u);
  EXPECT_NE(scene->warnings[0].find("boxing_toes_short.bvh:128:12:"), std::string::npos) << scene->warnings[0];
  EXPECT_NE(scene->warnings[0].find("79"), std::string::npos);
  EXPECT_NE(scene->warnings[0].find("80"), std::string::npos);
  ExpectFrameMatchesText(*scene, ReadText(FixturePath("bvh/boxing_toes_short.bvh")), 79, 0.01);

  ImportOptions strict;
  strict.strict = true;
  const Result<Scene> failed = ReadFixture("boxing_toes_short.bvh", strict);
  ASSERT_FALSE(failed.ok());
  EXPECT_EQ(failed.status().code(), ErrorCode::kInvalidData);
  EXPECT_NE(failed.status().message().find("boxing_toes_short.bvh:128:12: Frames declares 79 frames but the file holds 80"),
            std::string::npos)
      << failed.status().message();
}

TEST(BvhReader, CrlfFileReadsLikeTheOriginal) {
  const Result<Scene> crlf = ReadFixture("cmu_crlf.bvh");
  const Result<Scene> lf = ReadFixture("cmu_01_01_short.bvh");
  ASSERT_TRUE(crlf.ok()) << crlf.status().message();
  ASSERT_TRUE(lf.ok());
  ASSERT_EQ(crlf->clips[0].num_frames, 20);
  for (int f = 0; f < 20; ++f)
    for (int j = 0; j < 31; ++j) {
      EXPECT_EQ(crlf->clips[0].rotation(f, j).coeffs(), lf->clips[0].rotation(f, j).coeffs());
      EXPECT_EQ(crlf->clips[0].translation(f, j), lf->clips[0].translation(f, j));
    }
  EXPECT_EQ(crlf->skeleton.name(30), "RThumb");
}

TEST(BvhReader, MixedRotationOrdersGiveTheSameMotion) {
  const Result<Scene> mixed = ReadFixture("cmu_mixed_orders.bvh");
  const Result<Scene> original = ReadFixture("cmu_01_01_short.bvh");
  ASSERT_TRUE(mixed.ok()) << mixed.status().message();
  ASSERT_TRUE(original.ok());
  // Joint n uses order XYZ, XZY, YXZ, YZX, ZXY, ZYX, XYZ, ...
  EXPECT_EQ(mixed->skeleton.joint(0).bvh_channels[3], "Xrotation");
  EXPECT_EQ(mixed->skeleton.joint(1).bvh_channels,
            (std::vector<std::string>{"Xrotation", "Zrotation", "Yrotation"}));
  EXPECT_EQ(mixed->skeleton.joint(3).bvh_channels,
            (std::vector<std::string>{"Yrotation", "Zrotation", "Xrotation"}));
  const std::string text = ReadText(FixturePath("bvh/cmu_mixed_orders.bvh"));
  for (int frame : {0, 19}) ExpectFrameMatchesText(*mixed, text, frame, kCmuUnitM);
  for (int f = 0; f < 20; ++f)
    for (int j = 0; j < 31; ++j)
      EXPECT_LT(GeodesicAngle(mixed->clips[0].rotation(f, j), original->clips[0].rotation(f, j)) * kDegPerRad, 1e-9)
          << mixed->skeleton.name(j) << " frame " << f;
}

TEST(BvhReader, TwoRootsAreTwoTrees) {
  const Result<Scene> scene = ReadFixture("cmu_two_roots.bvh");
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_EQ(scene->skeleton.num_joints(), 62);
  EXPECT_EQ(scene->skeleton.Roots(), (std::vector<int>{0, 31}));
  EXPECT_EQ(scene->skeleton.name(31), "B:Hips");
  EXPECT_EQ(scene->skeleton.parent(32), 31);
  const MotionClip& clip = scene->clips[0];
  for (int f = 0; f < clip.num_frames; ++f) {
    EXPECT_NEAR(clip.translation(f, 31).x(), clip.translation(f, 0).x() + 50.0 * kCmuUnitM, kExactM);
    for (int j = 0; j < 31; ++j) EXPECT_EQ(clip.rotation(f, j).coeffs(), clip.rotation(f, j + 31).coeffs());
  }
  EXPECT_EQ(AnimatedJoints(*scene), (std::vector<std::string>{"Hips", "B:Hips"}));
}

TEST(BvhReader, NamesWithSpacesAndColonsArePreserved) {
  const Result<Scene> scene = ReadFixture("bandai_names.bvh");
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  for (const char* name : {"mixamorig:Root", "Spine Lower", "Bip01 Spine1", "Left Hand:Palm.001", "mixamorig:Right Toe"})
    EXPECT_TRUE(scene->skeleton.Find(name).has_value()) << name;
  const Result<Scene> original = ReadFixture("bandai_walk_normal_001_short.bvh");
  ASSERT_TRUE(original.ok());
  for (int f = 0; f < 10; ++f)
    for (int j = 0; j < 22; ++j) {
      EXPECT_EQ(scene->clips[0].rotation(f, j).coeffs(), original->clips[0].rotation(f, j).coeffs());
      EXPECT_EQ(scene->clips[0].translation(f, j), original->clips[0].translation(f, j));
    }
}

TEST(BvhReader, InterleavedChannelsAreMappedByName) {
  const Result<Scene> scene = ReadFixture("boxing_interleaved.bvh");
  const Result<Scene> original = ReadFixture("boxing_toes_short.bvh");
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_TRUE(original.ok());
  EXPECT_EQ(scene->skeleton.joint(0).bvh_channels,
            (std::vector<std::string>{"Zrotation", "Xposition", "Xrotation", "Yposition", "Zposition", "Yrotation"}));
  EXPECT_EQ(scene->skeleton.joint(2).bvh_channels,
            (std::vector<std::string>{"Yposition", "Zrotation", "Xrotation", "Yrotation"}));
  for (int f = 0; f < 10; ++f)
    for (int j = 0; j < 21; ++j) {
      EXPECT_LT(GeodesicAngle(scene->clips[0].rotation(f, j), original->clips[0].rotation(f, j)), 1e-15);
      EXPECT_LT((scene->clips[0].translation(f, j) - original->clips[0].translation(f, j)).norm(), kExactM);
    }
  // Ab's and Chest's position channels repeat their OFFSETs: not animated, no separate OFFSET to keep.
  EXPECT_EQ(AnimatedJoints(*scene), std::vector<std::string>{"Hips"});
  EXPECT_FALSE(scene->skeleton.joint(1).bvh_offset.has_value());
  EXPECT_FALSE(scene->skeleton.joint(2).bvh_offset.has_value());
}

TEST(BvhReader, ZUpOptionTurnsTheWholeMotionAtTheRoots) {
  ImportOptions z_up;
  z_up.up = "z";
  z_up.unit = "cmu";  // the height along Z of a Y-up file would pick another unit
  ImportOptions y_up;
  y_up.unit = "cmu";
  const Result<Scene> turned = ReadFixture("cmu_01_01_short.bvh", z_up);
  const Result<Scene> plain = ReadFixture("cmu_01_01_short.bvh", y_up);
  ASSERT_TRUE(turned.ok()) << turned.status().message();
  ASSERT_TRUE(plain.ok());
  EXPECT_EQ(turned->source.up_axis, "z");
  const auto a = ComputeWorldPositions(turned->skeleton, turned->clips[0]);
  const auto b = ComputeWorldPositions(plain->skeleton, plain->clips[0]);
  for (size_t i = 0; i < a.size(); ++i) {
    // Z-up (x, y, z) becomes Y-up (x, z, -y).
    EXPECT_NEAR(a[i].x(), b[i].x(), kExactM);
    EXPECT_NEAR(a[i].y(), b[i].z(), kExactM);
    EXPECT_NEAR(a[i].z(), -b[i].y(), kExactM);
  }
}

TEST(BvhReader, UnitOptionOverridesDetection) {
  ImportOptions cm;
  cm.unit = "cm";
  const Result<Scene> scene = ReadFixture("cmu_01_01_short.bvh", cm);
  ASSERT_TRUE(scene.ok());
  EXPECT_EQ(scene->source.unit_name, "cm");
  EXPECT_FALSE(scene->source.unit_detected);
  EXPECT_NEAR(scene->clips[0].translation(0, 0).y(), 0.178693, kExactM);
}

TEST(BvhReader, RejectsUnknownOptions) {
  ImportOptions bad_up;
  bad_up.up = "w";
  EXPECT_EQ(ReadFixture("cmu_01_01_short.bvh", bad_up).status().code(), ErrorCode::kInvalidArgument);
  ImportOptions bad_unit;
  bad_unit.unit = "furlong";
  EXPECT_EQ(ReadFixture("cmu_01_01_short.bvh", bad_unit).status().code(), ErrorCode::kInvalidArgument);
}

}  // namespace
}  // namespace mocapfill
