// CLI contract tests of the plumbing every verb shares, on the shipped fixtures.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

#include "formats/motion_io.h"
#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

namespace fs = std::filesystem;
using testing::RunCli;

std::string Quote(const std::string& s) { return "'" + s + "'"; }
std::string Fixture(const std::string& relative) { return Quote(testing::FixturePath(relative)); }

TEST(PlumbingCli, ConvertReadsStdinAndWritesStdout) {
  const std::string dir = testing::TestOutputDir("plumbing_cli");
  const std::string out = dir + "/stdin_stdout.glb";
  const testing::RunResult piped = testing::RunCliStdout("convert - - --from bvh --format glb < " +
                                                         Fixture("bvh/cmu_01_01_short.bvh") + " > " + Quote(out));
  ASSERT_EQ(piped.exit_code, 0) << piped.output;
  const Result<Scene> read = ImportFile(out);
  const Result<Scene> source = ImportFile(testing::FixturePath("bvh/cmu_01_01_short.bvh"));
  ASSERT_TRUE(read.ok() && source.ok());
  EXPECT_EQ(read->skeleton.num_joints(), source->skeleton.num_joints());
  EXPECT_EQ(read->clips.front().num_frames, source->clips.front().num_frames);
  EXPECT_EQ(read->clips.front().name, "stdin");  // not a temporary file's name
  // BVH on standard output, read back.
  const testing::RunResult bvh = testing::RunCliStdout("convert " + Quote(out) + " - --format bvh > " + Quote(dir + "/piped.bvh"));
  ASSERT_EQ(bvh.exit_code, 0);
  EXPECT_EQ(testing::ReadAll(dir + "/piped.bvh").rfind("HIERARCHY", 0), 0u);
}

TEST(PlumbingCli, StdinErrorsNameTheStream) {
  const std::string dir = testing::ScratchDir("plumbing_stdin_errors");
  const testing::RunResult no_format = RunCli("convert - " + Quote(dir + "/x.glb") + " < " + Fixture("bvh/cmu_01_01_short.bvh"));
  EXPECT_EQ(no_format.exit_code, 1) << no_format.output;
  EXPECT_NE(no_format.output.find("--from"), std::string::npos) << no_format.output;
  const testing::RunResult bad = RunCli("convert - " + Quote(dir + "/x.glb") + " --from bvh < " + Fixture("bad/nan_value.bvh"));
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("error: -:189:"), std::string::npos) << bad.output;  // line of the stream, no temporary path
  EXPECT_FALSE(fs::exists(dir + "/x.glb"));
  // A failure writes nothing on standard output.
  const testing::RunResult to_stdout = testing::RunCliStdout("convert - - --from bvh < " + Fixture("bad/nan_value.bvh") +
                                                             " > " + Quote(dir + "/piped.glb"));
  EXPECT_EQ(to_stdout.exit_code, 2);
  EXPECT_EQ(fs::file_size(dir + "/piped.glb"), 0u);
}

TEST(PlumbingCli, ConvertFolderWithJsonSummary) {
  const std::string dir = testing::TestOutputDir("plumbing_cli/folder");
  const testing::RunResult r = testing::RunCliStdout("convert " + Fixture("rigs") + " -o " + Quote(dir) + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  const Result<std::vector<std::string>> inputs = ListMotionFiles({testing::FixturePath("rigs")});
  ASSERT_TRUE(inputs.ok());
  EXPECT_EQ(j["converted"], inputs->size());
  EXPECT_EQ(j["failed"], 0);
  for (const auto& file : j["files"]) {
    EXPECT_TRUE(file["ok"].get<bool>());
    EXPECT_TRUE(fs::exists(file["output"].get<std::string>())) << file["output"];
  }
}

TEST(PlumbingCli, ConvertJsonReportsFailures) {
  const std::string dir = testing::ScratchDir("plumbing_json_failures");
  const testing::RunResult r = testing::RunCliStdout("convert " + Fixture("bad/garbage.bvh") + " " +
                                                     Fixture("bvh/cmu_crlf.bvh") + " -o " + Quote(dir) + " --json");
  EXPECT_EQ(r.exit_code, 2);
  const nlohmann::json j = nlohmann::json::parse(r.output);
  EXPECT_EQ(j["converted"], 1);
  EXPECT_EQ(j["failed"], 1);
  EXPECT_EQ(j["files"][0]["exit_code"], 2);
  EXPECT_NE(j["files"][0]["error"].get<std::string>().find("garbage.bvh"), std::string::npos);
}

TEST(PlumbingCli, FillPipesAndPrintsItsReport) {
  const std::string dir = testing::TestOutputDir("plumbing_cli");
  const testing::RunResult piped = testing::RunCliStdout("fill - --from bvh -o - --format glb --db default -q < " +
                                          Fixture("sketches/walk_proud_002_legs8.bvh") + " > " + Quote(dir + "/fill_piped.glb"));
  ASSERT_EQ(piped.exit_code, 0) << piped.output;
  const Result<Scene> filled = ImportFile(dir + "/fill_piped.glb");
  ASSERT_TRUE(filled.ok()) << filled.status().message();
  EXPECT_EQ(filled->clips.size(), 1u);
  const testing::RunResult json = testing::RunCliStdout("fill " + Fixture("sketches/walk_proud_002_legs8.glb") + " -o " +
                                                        Quote(dir + "/fill_json.glb") + " --json");
  ASSERT_EQ(json.exit_code, 0) << json.output;
  const nlohmann::json report = nlohmann::json::parse(json.output);
  EXPECT_EQ(report["database"], "default");
  EXPECT_LT(report["key_error_max_deg"].get<double>(), 0.01);
}

TEST(PlumbingCli, RunReportCarriesTheFillReport) {
  const std::string dir = testing::ScratchDir("plumbing_run_json");
  const testing::RunResult r = testing::RunCliStdout("run " + Fixture("pipelines/fill_default.json") + " --set out.path=" +
                                                     Quote(dir + "/out.glb") + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json j = nlohmann::json::parse(r.output);
  bool found = false;
  for (const auto& node : j["nodes"])
    if (node["type"] == "fill") {
      found = true;
      EXPECT_LT(node["report"]["key_error_max_deg"].get<double>(), 0.01);
      EXPECT_FALSE(node["report"]["joints"].empty());
    }
  EXPECT_TRUE(found) << r.output;
}

// One option schema for the fill: the verb's flags are generated from the fill node's options,
// so a value out of range gets the same message from both (named by flag or by option), and
// the spellings the verb always had (--fragment-hz, --feet plant|free, --texture on|off,
// repeated --dial) still parse.
TEST(PlumbingCli, FillFlagsAndFillNodeShareOneSchema) {
  const std::string dir = testing::ScratchDir("plumbing_fill_schema");
  const std::string sketch = Fixture("sketches/walk_proud_002_legs8.glb");
  const testing::RunResult flag = RunCli("fill " + sketch + " -o " + Quote(dir + "/a.glb") + " --candidates 0");
  EXPECT_EQ(flag.exit_code, 1) << flag.output;
  EXPECT_NE(flag.output.find("--candidates: expected an integer in [1, 1024], got 0"), std::string::npos) << flag.output;
  EXPECT_FALSE(fs::exists(dir + "/a.glb"));
  const testing::RunResult node = RunCli("run " + Fixture("pipelines/fill_default.json") + " --set out.path=" +
                                         Quote(dir + "/b.glb") + " --set fill.candidates=0");
  EXPECT_EQ(node.exit_code, 1) << node.output;
  EXPECT_NE(node.output.find("option \"candidates\": expected an integer in [1, 1024], got 0"), std::string::npos)
      << node.output;
  const testing::RunResult words = RunCli("fill " + sketch + " -o " + Quote(dir + "/c.glb") + " --texture maybe");
  EXPECT_EQ(words.exit_code, 1) << words.output;
  EXPECT_NE(words.output.find("--texture"), std::string::npos) << words.output;
  const testing::RunResult spelled =
      RunCli("-q fill " + sketch + " -o " + Quote(dir + "/d.glb") +
             " --fragment-hz 1 --feet free --texture off --coverage warn --method hybrid --dial 1=+0.5 --dial 2=-0.5"
             " --report " + Quote(dir + "/d.json"));
  ASSERT_EQ(spelled.exit_code, 0) << spelled.output;
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(dir + "/d.json"));
  EXPECT_EQ(report["method"], "hybrid");
  EXPECT_TRUE(report["feet"]["contacts"].empty()) << report["feet"];  // --feet free holds nothing
  // A list flag takes one value per occurrence: the sketch after it stays the positional input.
  const testing::RunResult lists =
      RunCli("-q fill --keep Hips --keep UpperLeg_L,LowerLeg_L " + sketch + " -o " + Quote(dir + "/e.glb") + " --json");
  ASSERT_EQ(lists.exit_code, 0) << lists.output;
}

TEST(PlumbingCli, DefaultDatabaseByName) {
  const testing::RunResult r = RunCli("db info default");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("default"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("21 clips"), std::string::npos) << r.output;
}

TEST(PlumbingCli, InlineJointNameMapForDatabases) {
  const testing::RunResult good = RunCli("db info " + Fixture("bvh/cmu_01_01_short.bvh") + " --map '{\"Hips\": \"Hips\"}'");
  EXPECT_EQ(good.exit_code, 0) << good.output;
  const testing::RunResult bad = RunCli("db info " + Fixture("bvh/cmu_01_01_short.bvh") + " --map '{\"Hips\": 3}'");
  EXPECT_EQ(bad.exit_code, 2) << bad.output;
  EXPECT_NE(bad.output.find("--map: \"Hips\": expected a name or \"\" (or null), got 3"), std::string::npos) << bad.output;
}

TEST(PlumbingCli, MisspeltJointsGetSuggestions) {
  const std::string dir = testing::ScratchDir("plumbing_suggestions");
  const testing::RunResult filter = RunCli("filter " + Fixture("bvh/cmu_01_01_short.bvh") + " -o " + Quote(dir + "/x.bvh") +
                                           " --joints LeftUpperLeg");
  EXPECT_EQ(filter.exit_code, 1) << filter.output;
  EXPECT_NE(filter.output.find("no joint named 'LeftUpperLeg' (closest: 'LeftUpLeg'"), std::string::npos) << filter.output;
  const testing::RunResult fill = RunCli("fill " + Fixture("sketches/walk_proud_002_legs8.glb") + " -o " +
                                         Quote(dir + "/x.glb") + " --keep Hips,Foot_LL");
  EXPECT_EQ(fill.exit_code, 1) << fill.output;
  EXPECT_NE(fill.output.find("keep: no joint named 'Foot_LL' (closest: 'Foot_L'"), std::string::npos) << fill.output;
  EXPECT_FALSE(fs::exists(dir + "/x.glb"));
}

TEST(PlumbingCli, GlobalFlagsAfterTheVerb) {
  const std::string dir = testing::ScratchDir("plumbing_quiet");
  const testing::RunResult r = RunCli("fill " + Fixture("sketches/walk_proud_002_legs8.glb") + " -o " +
                                      Quote(dir + "/x.glb") + " --quiet");
  EXPECT_EQ(r.exit_code, 0) << r.output;
  EXPECT_EQ(r.output, "");  // the summary is left out
}

}  // namespace
}  // namespace mocapfill
