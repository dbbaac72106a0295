// Broken BVH input: every reader error branch has a file in fixtures/bad/ or a small
// text here, and each error names the file, the line and the column. Random damage to a
// real file must give a clean error (or a valid scene), never a crash or a hang.
#include <gtest/gtest.h>

#include <random>

#include "formats/bvh/bvh_reader.h"
#include "tests/formats/bvh_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::FixturePath;
using testing::ReadText;

struct BadFile {
  const char* name;
  const char* location;  // "line:col" expected right after the file name
  const char* detail;    // a fragment the message must contain
};

class BvhBadFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(BvhBadFile, FailsWithFileLineAndColumn) {
  const BadFile& bad = GetParam();
  const std::string path = FixturePath(std::string("bad/") + bad.name);
  const Result<Scene> scene = ReadBvh(ReadText(path), path, {});
  ASSERT_FALSE(scene.ok()) << bad.name;
  EXPECT_EQ(scene.status().code(), ErrorCode::kInvalidData);
  const std::string& message = scene.status().message();
  EXPECT_EQ(message.rfind(path + ":" + bad.location + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(bad.detail), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, BvhBadFile,
    ::testing::Values(
        BadFile{"truncated.bvh", "190:304", "truncated in frame 2 (0-based; 2 complete of 3 declared): the row has 40 of 96"},
        BadFile{"nan_value.bvh", "189:79", "expected a finite number, got 'nan' in frame 1"},
        BadFile{"inf_value.bvh", "190:41", "expected a finite number, got '-inf' in frame 2"},
        BadFile{"wrong_channel_count.bvh", "10:3", "'LHipJoint' declares 4 channels but lists 3 before 'JOINT'"},
        BadFile{"unknown_channel.bvh", "13:35", "unknown channel 'Wrotation'"},
        BadFile{"zero_frames.bvh", "186:9", "no frames"},
        BadFile{"absurd_frames.bvh", "186:9", "'1000000000000' is out of range"},
        BadFile{"garbage.bvh", "1:1", "expected 'HIERARCHY'"},
        BadFile{"missing_brace.bvh", "184:1", "expected '}' to close joint 'Hips' (opened at line 2), got 'MOTION'"}),
    [](const ::testing::TestParamInfo<BadFile>& param) {
      std::string name = param.param.name;
      return name.substr(0, name.find('.'));
    });

// Small texts for the remaining branches, built around Boxing_Toes' first joint.
std::string Hips(const std::string& body, const std::string& motion = "Frames: 1\nFrame Time: 0.01\n1 2 3 4 5 6\n") {
  return "HIERARCHY\nROOT Hips\n{\n" + body + "}\nMOTION\n" + motion;
}
const std::string kGoodBody =
    "OFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation\n"
    "End Site\n{\nOFFSET 0 17 0\n}\n";

TEST(BvhBadText, EachErrorNamesItsPlace) {
  const std::pair<std::string, std::string> cases[] = {
      {"", "inline.bvh:1:1: expected 'HIERARCHY' at the start of a BVH file, got the end of the file"},
      {"HIERARCHY\nROOT Hips\n{\nOFFSET 0 0", "inline.bvh:4:11: expected a number for the Z offset of joint 'Hips'"},
      {"HIERARCHY\nJOINT Hips\n", "inline.bvh:2:1: expected ROOT or MOTION, got 'JOINT'"},
      {"HIERARCHY\nMOTION\n", "inline.bvh:2:1: MOTION before any ROOT"},
      {"HIERARCHY\nROOT\n{\n", "inline.bvh:2:5: expected a joint name after ROOT"},
      {Hips("OFFSET 0 0 0\nOFFSET 1 1 1\n"), "inline.bvh:5:1: second OFFSET in joint 'Hips'"},
      {Hips("CHANNELS 0\n"), "inline.bvh:2:1: joint 'Hips' has no OFFSET"},
      {Hips("OFFSET 0 0 abc\n"), "inline.bvh:4:12: expected a number for the Z offset of joint 'Hips', got 'abc'"},
      {Hips("OFFSET 0 0 nan\n"), "inline.bvh:4:12: expected a finite number for the Z offset"},
      {Hips("OFFSET 0 0 1e999\n"), "inline.bvh:4:12: number '1e999' for the Z offset of joint 'Hips' is out of range"},
      {Hips("OFFSET 0 0 0\nCHANNELS 7 Xposition\n"), "inline.bvh:5:10: the CHANNELS count of joint 'Hips' '7' is out of range (at most 6)"},
      {Hips("OFFSET 0 0 0\nCHANNELS -1\n"), "inline.bvh:5:10: expected a non-negative whole number"},
      {Hips("OFFSET 0 0 0\nCHANNELS 2 Xrotation Xrotation\n"), "inline.bvh:5:22: channel 'Xrotation' is listed twice"},
      {Hips("OFFSET 0 0 0\nCHANNELS 1 Xrotation Yrotation\n"), "inline.bvh:5:22: channel name 'Yrotation' after the CHANNELS list"},
      {Hips("OFFSET 0 0 0\nCHANNELS 0\nCHANNELS 0\n"), "inline.bvh:6:1: second CHANNELS line in joint 'Hips'"},
      {Hips("OFFSET 0 0 0\nROTATE 1\n"), "inline.bvh:5:1: expected OFFSET, CHANNELS, JOINT, End Site or '}' in joint 'Hips', got 'ROTATE'"},
      {Hips("OFFSET 0 0 0\nJOINT Hips\n{\nOFFSET 0 0 0\n}\n"), "inline.bvh:5:1: duplicate joint name 'Hips' (first defined at line 2)"},
      {Hips("OFFSET 0 0 0\nJOINT Ab\nOFFSET 0 0 0\n"), "inline.bvh:6:1: expected '{' after joint 'Ab', got 'OFFSET'"},
      {Hips("OFFSET 0 0 0\nEnd Point\n"), "inline.bvh:5:5: expected 'Site' after 'End', got 'Point'"},
      {Hips("OFFSET 0 0 0\nEnd Site\n{\n}\n"), "inline.bvh:7:1: expected OFFSET in the End Site of joint 'Hips', got '}'"},
      {Hips("OFFSET 0 0 0\nEnd Site\n{\nOFFSET 0 0 0\nCHANNELS 0\n"), "inline.bvh:8:1: expected '}' to close the End Site"},
      {Hips(kGoodBody, "Frame: 1\n"), "inline.bvh:12:1: expected 'Frames:', got 'Frame:'"},
      {Hips(kGoodBody, "Frames: -3\n"), "inline.bvh:12:9: expected a non-negative whole number for the Frames count, got '-3'"},
      {Hips(kGoodBody, "Frames: 1\nFrameTime: 0.01\n"), "inline.bvh:13:1: expected 'Frame Time:', got 'FrameTime:'"},
      {Hips(kGoodBody, "Frames: 1\nFrame Time: 0\n1 2 3 4 5 6\n"), "inline.bvh:13:13: the Frame Time must be positive, got '0'"},
      {Hips(kGoodBody, "Frames: 1\nFrame Time: 0.01 1 2\n"), "inline.bvh:13:18: unexpected '1' after the Frame Time"},
      {Hips(kGoodBody, "Frames: 2\nFrame Time: 0.01\n1 2 3 4 5 6\n1 2 3 4 5\n1 2 3 4 5 6\n"),
       "inline.bvh:15:10: frame 1 has 5 values, expected 6"},
      {Hips(kGoodBody, "Frames: 1\nFrame Time: 0.01\n1 2 3 4 5 6 7\n"), "inline.bvh:14:13: frame 0 has more than 6 values: unexpected '7'"},
      {Hips(kGoodBody, "Frames: 1\nFrame Time: 0.01\n1 2 3 4 5 6x\n"), "inline.bvh:14:11: expected a number, got '6x' in frame 0"},
      {Hips(kGoodBody, "Frames: 1\nFrame Time: 0.01\n1 2 3 4 5 1e400\n"), "inline.bvh:14:11: number '1e400' is out of range in frame 0"},
      {Hips("OFFSET 0 0 0\nCHANNELS 0\n", "Frames: 1\nFrame Time: 0.01\n\n"), "inline.bvh:8:9: the hierarchy declares no channels"},
  };
  for (const auto& [text, expected] : cases) {
    const Result<Scene> scene = ReadBvh(text, "inline.bvh", {});
    ASSERT_FALSE(scene.ok()) << expected;
    EXPECT_EQ(scene.status().code(), ErrorCode::kInvalidData) << expected;
    EXPECT_EQ(scene.status().message().rfind(expected, 0), 0u) << "got:      " << scene.status().message()
                                                                 << "\nexpected: " << expected;
  }
}

TEST(BvhBadText, SecondEndSiteIsAWarning) {
  ImportOptions cm;
  cm.unit = "cm";
  const Result<Scene> scene = ReadBvh(Hips(kGoodBody + "End Site\n{\nOFFSET 0 1 0\n}\n"), "inline.bvh", cm);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_EQ(scene->warnings.size(), 1u);
  EXPECT_EQ(scene->warnings[0].rfind("inline.bvh:10:1: joint 'Hips' has a second End Site", 0), 0u) << scene->warnings[0];
  EXPECT_EQ(scene->skeleton.joint(0).end_site->y(), 0.17);
}

TEST(BvhBadText, FewerRowsThanDeclaredIsAWarningWhenTheLastRowIsComplete) {
  const Result<Scene> scene =
      ReadBvh(Hips(kGoodBody, "Frames: 3\nFrame Time: 0.01\n1 2 3 4 5 6\n1 2 3 4 5 6"), "inline.bvh", {});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->clips[0].num_frames, 2);
  ASSERT_EQ(scene->warnings.size(), 1u);
  EXPECT_NE(scene->warnings[0].find("declares 3 frames but the file holds 2 rows"), std::string::npos);
}

// Random byte damage and cuts of a real file: every outcome is a scene or an
// InvalidData error that names the file; nothing crashes (run under the sanitizers in CI).
TEST(BvhBadText, RandomDamageNeverCrashes) {
  const std::string original = ReadText(FixturePath("bvh/cmu_crlf.bvh"));
  std::mt19937 rng(11);
  const char replacements[] = {'\0', '\n', '\r', ' ', '{', '}', '-', '.', 'e', 'x', '\xff', '9'};
  int failures = 0;
  for (int n = 0; n < 3000; ++n) {
    std::string text = original;
    if (n % 3 == 0) {
      text.resize(rng() % text.size());
    } else {
      for (int k = 0; k < 1 + n % 4; ++k) text[rng() % text.size()] = replacements[rng() % sizeof(replacements)];
    }
    const Result<Scene> scene = ReadBvh(text, "damaged.bvh", {});
    if (scene.ok()) {
      EXPECT_TRUE(scene->clips[0].Validate(scene->skeleton).ok());
      continue;
    }
    ++failures;
    EXPECT_EQ(scene.status().code(), ErrorCode::kInvalidData) << scene.status().message();
    EXPECT_EQ(scene.status().message().rfind("damaged.bvh:", 0), 0u) << scene.status().message();
  }
  EXPECT_GT(failures, 1000);
}

}  // namespace
}  // namespace mocapfill
