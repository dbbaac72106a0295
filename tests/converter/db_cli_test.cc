// CLI contract tests of db build/info, filter and analyze: exit codes, messages naming the
// file, no output on failure, outputs that load.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>

#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::ReadAll;
using testing::RunCli;
using testing::RunResult;

namespace fs = std::filesystem;

void WriteAll(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary);
  out << bytes;
}

// A small database folder: two shipped Bandai-Namco-skeleton clips.
std::string FixtureFolder(const std::string& name) {
  const std::string dir = testing::ScratchDir(name);
  fs::create_directories(dir + "/clips");
  fs::copy_file(testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"), dir + "/clips/walk_a.bvh");
  fs::copy_file(testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"), dir + "/clips/walk_b.bvh");
  return dir;
}

TEST(DbCli, BuildThenInfoReportsTheDatabase) {
  const std::string dir = FixtureFolder("db_cli_build");
  const std::string db = dir + "/small.mfdb";
  RunResult build = RunCli("db build " + dir + "/clips -o " + db);
  ASSERT_EQ(build.exit_code, 0) << build.output;
  EXPECT_NE(build.output.find("2 clips"), std::string::npos) << build.output;
  const std::string first = ReadAll(db);
  ASSERT_EQ(RunCli("-q db build " + dir + "/clips -o " + dir + "/again.mfdb").exit_code, 0);
  EXPECT_EQ(first, ReadAll(dir + "/again.mfdb"));  // deterministic bytes
  for (const std::string& source : {db, dir + "/clips"}) {
    RunResult info = RunCli("db info " + source + " --json");
    ASSERT_EQ(info.exit_code, 0) << info.output;
    const nlohmann::json json = nlohmann::json::parse(info.output);
    EXPECT_EQ(json["clips"], 2);
    EXPECT_EQ(json["joints"], 22);
    EXPECT_EQ(json["root_joint"], "Hips");
    EXPECT_GE(json["load_ms"].get<double>(), 0.0);
  }
  // Info on a folder builds in memory and writes nothing.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir + "/clips"), fs::directory_iterator{}), 2);
}

TEST(DbCli, MirrorOnAddsEachClipsMirrorImageAndRefusesOtherValues) {
  const std::string dir = FixtureFolder("db_cli_mirror");
  const std::string db = dir + "/mirrored.mfdb";
  RunResult build = RunCli("db build " + dir + "/clips -o " + db + " --mirror on");
  ASSERT_EQ(build.exit_code, 0) << build.output;
  RunResult info = RunCli("db info " + db + " --json --clips");
  ASSERT_EQ(info.exit_code, 0) << info.output;
  const nlohmann::json json = nlohmann::json::parse(info.output);
  ASSERT_EQ(json["clips"], 4);
  EXPECT_EQ(json["clip_list"][2]["name"], json["clip_list"][0]["name"].get<std::string>() + "#mirror");
  EXPECT_EQ(json["clip_list"][2]["labels"], json["clip_list"][0]["labels"]);
  RunResult bad = RunCli("db build " + dir + "/clips -o " + dir + "/bad.mfdb --mirror yes");
  EXPECT_EQ(bad.exit_code, 1);
  EXPECT_NE(bad.output.find("--mirror"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir + "/bad.mfdb"));
}

TEST(DbCli, CorruptedTruncatedAndForeignFilesExitWith2) {
  const std::string dir = FixtureFolder("db_cli_bad");
  const std::string db = dir + "/good.mfdb";
  ASSERT_EQ(RunCli("-q db build " + dir + "/clips -o " + db).exit_code, 0);
  const std::string bytes = ReadAll(db);
  std::string flipped = bytes;
  flipped[bytes.size() / 2] ^= 0x01;
  WriteAll(dir + "/flipped.mfdb", flipped);
  WriteAll(dir + "/truncated.mfdb", bytes.substr(0, bytes.size() / 2));
  std::string magic = bytes;
  magic[1] = 'X';
  WriteAll(dir + "/magic.mfdb", magic);
  std::string version = bytes;
  version[8] = 9;
  WriteAll(dir + "/version.mfdb", version);
  const std::pair<const char*, const char*> cases[] = {{"flipped", "checksum mismatch"},
                                                       {"truncated", "truncated"},
                                                       {"magic", "bad magic"},
                                                       {"version", "unsupported .mfdb version 9"}};
  for (const auto& [name, message] : cases) {
    const std::string path = dir + "/" + name + ".mfdb";
    RunResult info = RunCli("db info " + path);
    EXPECT_EQ(info.exit_code, 2) << name << ": " << info.output;
    EXPECT_NE(info.output.find(path), std::string::npos) << info.output;
    EXPECT_NE(info.output.find(message), std::string::npos) << info.output;
    RunResult analyze = RunCli("analyze " + testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh") + " --db " + path);
    EXPECT_EQ(analyze.exit_code, 2) << analyze.output;
  }
}

TEST(DbCli, UsageErrorsExitWith1AndWriteNothing) {
  const std::string dir = FixtureFolder("db_cli_usage");
  EXPECT_EQ(RunCli("db build " + dir + "/clips").exit_code, 1);  // no -o
  EXPECT_EQ(RunCli("db build " + dir + "/clips -o " + dir + "/x.bin").exit_code, 1);
  EXPECT_FALSE(fs::exists(dir + "/x.bin"));
  EXPECT_EQ(RunCli("db").exit_code, 1);
  const std::string in = testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh");
  RunResult joints = RunCli("filter " + in + " -o " + dir + "/f.glb --joints NoSuchJoint");
  EXPECT_EQ(joints.exit_code, 1);
  EXPECT_NE(joints.output.find("NoSuchJoint"), std::string::npos);
  RunResult gains = RunCli("filter " + in + " -o " + dir + "/f.glb --gains 1,1,1,1,1,1,1,1,1,1,1,1,2");
  EXPECT_EQ(gains.exit_code, 1);
  EXPECT_NE(gains.output.find("band L12"), std::string::npos) << gains.output;
  EXPECT_FALSE(fs::exists(dir + "/f.glb"));
  // A clip of another humanoid rig is retargeted onto the database's rig; one that is
  // not humanoid is refused naming the file, and nothing is written.
  std::string renamed = ReadAll(in);
  renamed.replace(renamed.find("UpperArm_L"), 10, "LeftArm123");
  WriteAll(dir + "/clips/zz_renamed.bvh", renamed);  // added last
  RunResult retargeted = RunCli("db build " + dir + "/clips -o " + dir + "/m.mfdb");
  EXPECT_EQ(retargeted.exit_code, 0) << retargeted.output;
  fs::remove(dir + "/m.mfdb");
  fs::copy_file(testing::FixturePath("gltf/simple_skin.gltf"), dir + "/clips/zzz_tentacle.gltf");
  RunResult mismatch = RunCli("db build " + dir + "/clips -o " + dir + "/m.mfdb");
  EXPECT_EQ(mismatch.exit_code, 2) << mismatch.output;
  EXPECT_NE(mismatch.output.find("zzz_tentacle.gltf"), std::string::npos) << mismatch.output;
  EXPECT_NE(mismatch.output.find("humanoid"), std::string::npos) << mismatch.output;
  EXPECT_FALSE(fs::exists(dir + "/m.mfdb"));
  fs::remove(dir + "/clips/zzz_tentacle.gltf");
  // A map that renames joints makes the skeletons match by name instead.
  WriteAll(dir + "/map.json", "{\"LeftArm123\": \"UpperArm_L\"}");
  EXPECT_EQ(RunCli("-q db build " + dir + "/clips -o " + dir + "/m.mfdb --map " + dir + "/map.json").exit_code, 0);
}

TEST(FilterCli, WritesAValidGltfWithBandGains) {
  const std::string out = testing::TestOutputDir("filter") + "/cli_walk_gains.glb";
  fs::remove(out);
  const std::string in = testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh");
  RunResult run = RunCli("filter " + in + " -o " + out + " --gains 1,1,1.5,1.5,1,1 --joints UpperArm_L,LowerArm_L");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("L2 2Hz x1.5"), std::string::npos) << run.output;
  EXPECT_TRUE(fs::exists(out));
  RunResult inspect = RunCli("inspect " + out + " --json");
  ASSERT_EQ(inspect.exit_code, 0);
  EXPECT_EQ(nlohmann::json::parse(inspect.output)["skeleton"]["joints"], 22);
}

TEST(AnalyzeCli, ReportsPhasesAndWritesAPlot) {
  const std::string dir = testing::ScratchDir("analyze_cli");
  const std::string in = testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh");
  RunResult run = RunCli("analyze " + in + " --json --plot " + dir + "/curves.svg --joint UpperLeg_L --axis y");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json json = nlohmann::json::parse(run.output);
  EXPECT_EQ(json["phases"]["master"], "UpperLeg_L.y");
  EXPECT_GE(json["phases"]["list"].size(), 3u);
  EXPECT_EQ(json["correlation"]["source"], "clip");
  const std::string svg = ReadAll(dir + "/curves.svg");
  EXPECT_NE(svg.find("time (s)"), std::string::npos);
  EXPECT_NE(svg.find("angle (deg)"), std::string::npos);
  EXPECT_NE(svg.find("stroke-dasharray"), std::string::npos);  // phase boundaries
  EXPECT_EQ(RunCli("analyze " + in + " --plot " + dir + "/curves.png").exit_code, 1);
}

}  // namespace
}  // namespace mocapfill
