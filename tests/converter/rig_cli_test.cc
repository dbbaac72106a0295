// CLI contract tests of `mocapfill rig show`: text and JSON reports on shipped rigs, exit 2
// with a message naming the file on a non-humanoid rig or a bad map, nothing written.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>

#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

namespace fs = std::filesystem;
using testing::RunCli;

std::string Quote(const std::string& s) { return "'" + s + "'"; }

TEST(RigCli, TextReport) {
  const testing::RunResult r = RunCli("rig show " + Quote(testing::FixturePath("bvh/boxing_toes_short.bvh")));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("family:    biovision"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("leftUpperArm   LeftShoulder"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("leftShoulder   LeftCollar"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("rest:"), std::string::npos);
  EXPECT_NE(r.output.find("proportions (m)"), std::string::npos);
}

TEST(RigCli, JsonReport) {
  const testing::RunResult r = RunCli("rig show --json " + Quote(testing::FixturePath("rigs/smpl_body.bvh")));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["family"], "smpl");
  EXPECT_EQ(j["bones"]["leftUpperArm"], "L_Shoulder");
  EXPECT_EQ(j["bones"]["leftToes"], "L_Foot");
  EXPECT_TRUE(j["missing_bones"].empty() || j["missing_bones"].is_array());
  EXPECT_EQ(j["rest"]["source"], "zero");
  EXPECT_GT(j["proportions_m"]["hip_height"].get<double>(), 0.8);
  EXPECT_LT(j["proportions_m"]["hip_height"].get<double>(), 1.0);
}

TEST(RigCli, MapAndRestOptions) {
  const std::string bandai = Quote(testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"));
  testing::RunResult r = RunCli("rig show --json --rest zero " + bandai);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(nlohmann::json::parse(r.output)["rest"]["source"], "zero");
  r = RunCli("rig show --json " + bandai);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(nlohmann::json::parse(r.output)["rest"]["source"], "mean");
  r = RunCli("rig show --json --rest first-frame " + bandai);
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(nlohmann::json::parse(r.output)["rest"]["source"], "first-frame");
  r = RunCli("rig show --json --rest middle " + bandai);
  EXPECT_EQ(r.exit_code, 1) << r.output;  // a usage error
  EXPECT_NE(r.output.find("mean"), std::string::npos) << r.output;
  r = RunCli("rig show " + bandai + " --map '{\"Toes_L\": \"\"}'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("leftToes       \xE2\x80\x94"), std::string::npos) << r.output;
  r = RunCli("rig show " + bandai + " --map '{\"Toes_LL\": \"leftToes\"}'");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("'Toes_L'"), std::string::npos) << r.output;
  EXPECT_EQ(RunCli("rig show --rest sideways " + bandai).exit_code, 1);
  EXPECT_EQ(RunCli("rig show").exit_code, 1);
}

TEST(RigCli, NonHumanoidExitsWithTwoAndWritesNothing) {
  const std::string dir = testing::ScratchDir("rig_cli_non_humanoid");
  const std::string input = testing::FixturePath("fbx/animation_with_skeleton.fbx");
  const testing::RunResult r = RunCli("rig show " + Quote(input));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("animation_with_skeleton.fbx"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("not a humanoid rig"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace
}  // namespace mocapfill
