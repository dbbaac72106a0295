// `mocapfill fill --method pca|hybrid` and `eval --methods ...,pca,hybrid` end to end on the
// shipped sketch and the embedded default database. Every glTF written under
// TestOutputDir() is checked by the Khronos validator in CI.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::ReadAll;
using testing::RunCli;
using testing::RunResult;

constexpr double kKeyToleranceDeg = 0.5;  // target mean key error of the subspace fit

std::string GlbSketch() { return testing::FixturePath("sketches/walk_proud_002_legs8.glb"); }

TEST(HybridCli, FillsTheSketchWithAReportOfStagesAndTheSolver) {
  const std::string out = testing::TestOutputDir("fill") + "/walk_proud_hybrid.glb";
  const std::string report = testing::ScratchDir("hybrid_report") + "/fill.json";
  const RunResult run = RunCli("fill " + GlbSketch() + " -o " + out + " --method hybrid --report " + report);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("pca fit: CONVERGENCE"), std::string::npos) << run.output;
  const nlohmann::json json = nlohmann::json::parse(ReadAll(report));
  EXPECT_EQ(json["method"], "hybrid");
  EXPECT_LT(json["key_error_mean_deg"].get<double>(), kKeyToleranceDeg);
  EXPECT_EQ(json["pca_model"]["source"], "built from the database");
  EXPECT_GT(json["pca_model"]["components"].get<int>(), 0);
  EXPECT_EQ(json["pca_solver"]["termination"], "CONVERGENCE");
  EXPECT_GE(json["pca_solver"]["iterations"].get<int>(), 1);
  EXPECT_LE(json["pca_solver"]["final_cost"].get<double>(), json["pca_solver"]["initial_cost"].get<double>());
  for (const char* stage : {"load_database", "pca_model", "fragments", "fragments.match", "pca_fit", "hybrid_texture"})
    EXPECT_TRUE(json["stage_seconds"].contains(stage)) << stage;
  EXPECT_FALSE(json["fragments"].empty());
}

TEST(HybridCli, UsesAGivenModelFullPoseVariantAndDials) {
  const std::string dir = testing::ScratchDir("hybrid_model");
  RunResult run = RunCli("-q pca build --db " + testing::FixturePath("default_db") + " -o " + dir + "/walk.pca");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const std::string out = testing::TestOutputDir("fill") + "/walk_proud_hybrid_fullpose_dial.glb";
  run = RunCli("fill " + GlbSketch() + " -o " + out + " --method hybrid --pca " + dir + "/walk.pca" +
               " --pca-fit full-pose --dial 1=+1.0 --report " + dir + "/fill.json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json json = nlohmann::json::parse(ReadAll(dir + "/fill.json"));
  EXPECT_EQ(json["pca_model"]["source"], "given");
  run = RunCli("fill " + GlbSketch() + " -o " + dir + "/bad.glb --method hybrid --dial x=1");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("--dial 'x=1'"), std::string::npos) << run.output;
  run = RunCli("fill " + GlbSketch() + " -o " + dir + "/bad.glb --method hybrid --pca " + dir + "/missing.pca");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_FALSE(std::ifstream(dir + "/bad.glb").good());  // no partial output
}

TEST(HybridCli, PcaMethodWritesAGltf) {
  const std::string out = testing::TestOutputDir("fill") + "/walk_proud_pca.glb";
  const RunResult run = RunCli("fill " + GlbSketch() + " -o " + out + " --method pca");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("keys: mean error 0.0000"), std::string::npos) << run.output;
}

TEST(HybridCli, EvalScoresPcaAndHybridOnTheDefaultDatabase) {
  const RunResult run = RunCli("-q eval --db " + testing::FixturePath("default_db") +
                               " --contents run --methods hierarchical,pca,hybrid --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json json = nlohmann::json::parse(run.output);
  EXPECT_EQ(json["protocol"]["folds"], 3);
  ASSERT_EQ(json["clips"].size(), 9u);  // 3 run clips x 3 methods
  for (const auto& row : json["summary"]) {
    if (row["category"] != "all") continue;
    for (const auto& [name, value] : row["metrics"].items())
      EXPECT_TRUE(std::isfinite(value.get<double>())) << row["method"] << " " << name;
    EXPECT_GT(row["metrics"]["mpjpe_unkeyed_cm"].get<double>(), 0.5);
    EXPECT_LT(row["metrics"]["mpjpe_unkeyed_cm"].get<double>(), 30.0);
    EXPECT_LT(row["metrics"]["key_error_mean_deg"].get<double>(), kKeyToleranceDeg);
    EXPECT_LT(row["metrics"]["bone_length_error"].get<double>(), 1e-9);
  }
}

}  // namespace
}  // namespace mocapfill
