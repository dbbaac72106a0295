// Every BVH of the shared corpus (174 Bandai-Namco clips, two CMU trials, Boxing_Toes)
// reads without error and survives BVH -> text -> BVH within the round-trip tolerances.
#include <gtest/gtest.h>

#include <filesystem>

#include "formats/bvh/bvh_reader.h"
#include "formats/bvh/bvh_writer.h"
#include "tests/formats/bvh_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

namespace fs = std::filesystem;

class BvhCorpus : public ::testing::TestWithParam<std::string> {};

TEST_P(BvhCorpus, ReadsAndRoundTripsThroughText) {
  MOCAPFILL_REQUIRE_CORPUS();
  const std::string path = GetParam();
  const Result<Scene> source = ReadBvh(testing::ReadText(path), path, {});
  ASSERT_TRUE(source.ok()) << source.status().message();
  ASSERT_TRUE(source->clips[0].Validate(source->skeleton).ok());
  const Result<std::string> text = WriteBvh(*source, {});
  ASSERT_TRUE(text.ok()) << text.status().message();
  const Result<Scene> back = ReadBvh(*text, path + " (rewritten)", {});
  ASSERT_TRUE(back.ok()) << back.status().message();
  testing::ExpectSameSkeleton(source->skeleton, back->skeleton, testing::kRoundTripTranslationToleranceM);
  EXPECT_EQ(back->clips[0].sample_rate_hz, source->clips[0].sample_rate_hz);
  const testing::MotionDifference d = testing::CompareMotion(*source, *back);
  EXPECT_LT(d.rotation_deg, testing::kRoundTripRotationToleranceDeg);
  EXPECT_LT(d.translation_m, testing::kRoundTripTranslationToleranceM);
  EXPECT_LT(testing::MaxRotationChannelJumpDeg(*text), 180.0);

  // Bandai-Namco: six channels everywhere, but only Hips (and in a few clips joint_Root) move.
  if (path.find("bandai-namco") != std::string::npos) {
    EXPECT_EQ(source->skeleton.num_joints(), 22);
    EXPECT_EQ(source->clips[0].sample_rate_hz, 30.0);
    for (int j = 0; j < source->skeleton.num_joints(); ++j) {
      if (!source->clips[0].translation_animated[j]) continue;
      EXPECT_TRUE(source->skeleton.name(j) == "Hips" || source->skeleton.name(j) == "joint_Root")
          << source->skeleton.name(j);
    }
  }
}

std::vector<std::string> AllCorpusBvh() {
  std::vector<std::string> files = testing::CorpusFiles("", ".bvh");
  if (files.empty()) files.push_back("");  // one visible skip instead of an empty suite
  return files;
}

INSTANTIATE_TEST_SUITE_P(AllBvh, BvhCorpus, ::testing::ValuesIn(AllCorpusBvh()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = param.param.empty() ? "no_corpus" : fs::path(param.param).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

TEST(BvhCorpusFiles, BoxingToesDeclaresOneFrameLessThanItHolds) {
  MOCAPFILL_REQUIRE_CORPUS();
  const std::string path = testing::DataPath("assimp/Boxing_Toes.bvh");
  const Result<Scene> scene = ReadBvh(testing::ReadText(path), path, {});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->clips[0].num_frames, 3070);
  ASSERT_EQ(scene->warnings.size(), 1u);
  EXPECT_NE(scene->warnings[0].find("Frames declares 3069 frames but the file holds 3070 rows"), std::string::npos)
      << scene->warnings[0];
  ImportOptions strict;
  strict.strict = true;
  const Result<Scene> failed = ReadBvh(testing::ReadText(path), path, strict);
  ASSERT_FALSE(failed.ok());
  EXPECT_EQ(failed.status().code(), ErrorCode::kInvalidData);
  EXPECT_NE(failed.status().message().find("Boxing_Toes.bvh:128:12:"), std::string::npos);
}

TEST(BvhCorpusFiles, CmuTrialsAre120HzInTheCmuUnit) {
  MOCAPFILL_REQUIRE_CORPUS();
  for (const std::string& path : testing::CorpusFiles("cmu", ".bvh")) {
    const Result<Scene> scene = ReadBvh(testing::ReadText(path), path, {});
    ASSERT_TRUE(scene.ok()) << scene.status().message();
    EXPECT_EQ(scene->clips[0].sample_rate_hz, 120.0) << path;
    EXPECT_EQ(scene->skeleton.num_joints(), 31) << path;
    EXPECT_EQ(scene->source.unit_name, "cmu") << path;
    EXPECT_EQ(scene->clips[0].num_frames, scene->source.declared_frames) << path;
  }
}

}  // namespace
}  // namespace mocapfill
