// `mocapfill fill` end to end on the shipped sketches and the embedded default database:
// outputs, report, determinism, key fidelity, and the rejected sketches (exit 2).
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "formats/motion_io.h"
#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::ReadAll;
using testing::RunCli;
using testing::RunResult;

namespace fs = std::filesystem;

constexpr double kKeyToleranceDeg = 0.5;  // target: mean key error below 0.5 degrees
const char* kLegs = "Hips,UpperLeg_L,LowerLeg_L,Foot_L,Toes_L,UpperLeg_R,LowerLeg_R,Foot_R,Toes_R";

std::string GlbSketch() { return testing::FixturePath("sketches/walk_proud_002_legs8.glb"); }
std::string BvhSketch() { return testing::FixturePath("sketches/walk_proud_002_legs8.bvh"); }

TEST(FillCli, FillsTheGltfSketchFromTheDefaultDatabaseWithAReport) {
  const std::string out = testing::TestOutputDir("fill") + "/walk_proud_hierarchical.glb";
  const std::string report = testing::ScratchDir("fill_report") + "/fill.json";
  const RunResult run = RunCli("fill " + GlbSketch() + " -o " + out + " --report " + report);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("keys: mean error"), std::string::npos) << run.output;
  const nlohmann::json json = nlohmann::json::parse(ReadAll(report));
  EXPECT_EQ(json["method"], "hierarchical");
  EXPECT_EQ(json["key_spacing_frames"], 8);
  EXPECT_LT(json["key_error_mean_deg"].get<double>(), kKeyToleranceDeg);
  EXPECT_LT(json["key_error_max_deg"].get<double>(), 0.01);  // read back, at the key times
  EXPECT_EQ(json["rate_hz"], 30.0);
  EXPECT_TRUE(json["rig"]["same_as_database"].get<bool>());
  int synthesized = 0, textured = 0, kept = 0;
  for (const auto& joint : json["joints"]) {
    if (joint["kind"] == "synthesized") ++synthesized;
    if (joint["kind"] == "textured") ++textured;
    if (joint["kind"] == "kept") ++kept;
  }
  EXPECT_EQ(textured, 9);      // root and legs, textured by default
  EXPECT_EQ(synthesized, 12);  // the upper body
  EXPECT_EQ(kept, 1);          // the static joint_Root, outside the canonical humanoid
  ASSERT_GT(json["fragments"].size(), 10u);
  EXPECT_NE(json["fragments"][0]["clip"].get<std::string>().find("dataset-1_"), std::string::npos);
  EXPECT_TRUE(json["stage_seconds"].contains("match"));

  Result<Scene> filled = ImportFile(out);
  ASSERT_TRUE(filled.ok()) << filled.status().message();
  Result<Scene> sketch = ImportFile(GlbSketch());
  ASSERT_TRUE(sketch.ok());
  ASSERT_EQ(filled->clips.size(), 1u);
  EXPECT_EQ(filled->clips[0].num_frames, sketch->clips[0].num_frames);
  EXPECT_EQ(filled->skeleton.num_joints(), sketch->skeleton.num_joints());
  // Every joint is now animated: the hand moves away from its rest pose.
  const int hand = *filled->skeleton.Find("Hand_L");
  double moved = 0.0;
  for (int f = 1; f < filled->clips[0].num_frames; ++f)
    moved = std::max(moved, filled->clips[0].rotation(f, hand).angularDistance(filled->clips[0].rotation(0, hand)));
  EXPECT_GT(moved, 0.05);
}

TEST(FillCli, FillsABakedBvhSketchWithKeep) {
  const std::string out = testing::TestOutputDir("fill") + "/walk_proud_from_bvh.glb";
  const RunResult run = RunCli("fill " + BvhSketch() + " -o " + out + " --keep " + kLegs + " --method fragment");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(out));
}

TEST(FillCli, SameBytesTwice) {
  const std::string dir = testing::ScratchDir("fill_determinism");
  for (const char* name : {"a.glb", "b.glb"})
    ASSERT_EQ(RunCli("-q fill " + GlbSketch() + " -o " + dir + "/" + name).exit_code, 0);
  EXPECT_EQ(ReadAll(dir + "/a.glb"), ReadAll(dir + "/b.glb"));
}

TEST(FillCli, EveryJoiningCriterionAndMethodRuns) {
  for (const char* flags : {"--join best-fragment", "--join cost-matrix --texture off", "--join best-animation",
                            "--method mean", "--method nn"}) {
    std::string file;
    for (const char* c = flags; *c; ++c)
      if (*c != '-' || (c > flags && c[-1] != '-' && c[-1] != ' ')) file += *c == ' ' ? '_' : *c;
    const std::string out = testing::TestOutputDir("fill") + "/walk_proud_" + file + ".glb";
    const RunResult run = RunCli("fill " + GlbSketch() + " -o " + out + " " + flags);
    EXPECT_EQ(run.exit_code, 0) << flags << ": " << run.output;
  }
}

TEST(FillCli, RejectsASketchWithoutKeyedJoints) {
  const std::string out = testing::ScratchDir("fill_nokeys") + "/out.glb";
  const RunResult run = RunCli("fill " + GlbSketch() + " -o " + out + " --synthesize " + kLegs);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("no keyed joint"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out));
}

// Another rig (CMU: other names, helper joints, 120 Hz) is mapped and filled on its own rig.
TEST(FillCli, FillsASketchOnAnotherRigAtItsOwnRate) {
  const std::string out = testing::TestOutputDir("fill") + "/cmu_01_01_filled.glb";
  const std::string report = testing::ScratchDir("fill_cmu") + "/fill.json";
  const RunResult run =
      RunCli("fill " + testing::FixturePath("bvh/cmu_01_01_short.bvh") + " -o " + out + " --report " + report +
             " --keep Hips,LeftUpLeg,LeftLeg,LeftFoot,LeftToeBase,RightUpLeg,RightLeg,RightFoot,RightToeBase");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json json = nlohmann::json::parse(ReadAll(report));
  EXPECT_FALSE(json["rig"]["same_as_database"].get<bool>());
  EXPECT_EQ(json["rate_hz"], 120.0);
  EXPECT_LT(json["key_error_max_deg"].get<double>(), 0.01);
  EXPECT_LT(json["max_frame_jump_deg"].get<double>(), 60.0);
  Result<Scene> filled = ImportFile(out);
  ASSERT_TRUE(filled.ok()) << filled.status().message();
  EXPECT_EQ(filled->skeleton.num_joints(), 31);  // CMU's own skeleton
  EXPECT_EQ(filled->clips[0].sample_rate_hz, 120.0);
}

TEST(FillCli, RejectsARigThatIsNotHumanoid) {
  const std::string out = testing::ScratchDir("fill_unknown") + "/out.glb";
  const RunResult run = RunCli("fill " + testing::FixturePath("gltf/simple_skin.gltf") + " -o " + out);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("humanoid"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(FillCli, RenamedSkeletonNeedsAMap) {
  const std::string dir = testing::ScratchDir("fill_map");
  const std::string sketch = testing::FixturePath("bvh/bandai_names.bvh");
  RunResult run = RunCli("fill " + sketch + " -o " + dir + "/out.glb");
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("--map"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(dir + "/out.glb"));
  std::ofstream(dir + "/map.json") << R"({"mixamorig:Root": "joint_Root", "Spine Lower": "Spine",
      "Bip01 Spine1": "Chest", "Left Hand:Palm.001": "Hand_L", "mixamorig:Right Toe": "Toes_R"})";
  run = RunCli("fill " + sketch + " -o " + dir + "/out.glb --map " + dir + "/map.json --keep Hips,UpperLeg_L");
  EXPECT_EQ(run.exit_code, 0) << run.output;
}

TEST(EvalCli, LeaveOneStyleOutOnTheDefaultDatabaseScoresEveryMethod) {
  const RunResult run = RunCli("-q eval --db " + testing::FixturePath("default_db") +
                               " --contents run --methods mean,hierarchical --json --split none");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json json = nlohmann::json::parse(run.output);
  EXPECT_EQ(json["protocol"]["folds"], 3);  // normal, happy, tired
  EXPECT_EQ(json["protocol"]["split"], "none");
  ASSERT_EQ(json["clips"].size(), 6u);      // 3 run clips x 2 methods
  double mean_cm = 0.0, hierarchical_cm = 0.0;
  for (const auto& row : json["summary"]) {
    EXPECT_EQ(row["half"], "all");
    if (row["category"] != "all") continue;
    EXPECT_EQ(row["clips"], 3);
    EXPECT_LT(row["metrics"]["bone_length_error"].get<double>(), 1e-9);
    EXPECT_LT(row["metrics"]["key_error_max_deg"].get<double>(), 1e-3);
    (row["method"] == "mean" ? mean_cm : hierarchical_cm) = row["metrics"]["mpjpe_unkeyed_cm"].get<double>();
  }
  EXPECT_GT(mean_cm, 5.0);  // the mean pose misses the arm swing by centimetres
  EXPECT_LT(hierarchical_cm, mean_cm);
}

// The split-half protocol on the default database's run clips: styles happy and tired form the
// tuning half (each against the other only), normal the reporting half (against both others).
// The JSON carries both halves, intervals, the difference to mean, penetration, floor glide and fold cells;
// the reporting fold scores exactly as in plain leave-one-out (same database).
TEST(EvalCli, SplitHalvesCarryIntervalsFoldCellsAndPenetration) {
  const std::string db = testing::FixturePath("default_db");
  const RunResult run = RunCli("-q eval --db " + db + " --contents run --methods mean,hierarchical --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json json = nlohmann::json::parse(run.output);
  EXPECT_EQ(json["protocol"]["split"], "both");
  EXPECT_EQ(json["protocol"]["halves"]["tuning"], nlohmann::json({"happy", "tired"}));
  EXPECT_EQ(json["protocol"]["halves"]["reporting"], nlohmann::json({"normal"}));
  EXPECT_EQ(json["protocol"]["bootstrap"]["resamples"], 2000);
  int tuning_rows = 0, reporting_rows = 0;
  for (const auto& row : json["summary"]) {
    if (row["category"] != "all") continue;
    const bool tuning = row["half"] == "tuning";
    (tuning ? tuning_rows : reporting_rows) += 1;
    EXPECT_EQ(row["clips"], tuning ? 2 : 1) << row.dump();
    const double unkeyed = row["metrics"]["mpjpe_unkeyed_cm"].get<double>();
    const auto& ci = row["intervals"]["mpjpe_unkeyed_cm"];
    EXPECT_LE(ci["lo"].get<double>(), unkeyed + 1e-9);
    EXPECT_GE(ci["hi"].get<double>(), unkeyed - 1e-9);
    EXPECT_GE(row["metrics"]["penetration_max_cm"].get<double>(), 0.0);
    EXPECT_TRUE(row["intervals"].contains("penetration_mean_cm"));
    EXPECT_TRUE(row["intervals"].contains("foot_skate_cm_per_s"));
    EXPECT_LE(row["metrics"]["foot_slide_cm_per_s"].get<double>(),
              row["metrics"]["foot_skate_cm_per_s"].get<double>() + 1e-9);  // a part of it
    EXPECT_TRUE(row["intervals"].contains("floor_glide_cm_per_s"));
    EXPECT_GT(row["metrics"]["capture_floor_steps"].get<long>(), 0);  // the runs' feet touch the floor
    if (row["method"] == "mean") {
      EXPECT_TRUE(row["below_mean"].is_null());
    } else {
      const auto& below = row["below_mean"];
      ASSERT_FALSE(below.is_null());
      EXPECT_LE(below["lo"].get<double>(), below["pct"].get<double>() + 1e-9);
      EXPECT_GE(below["hi"].get<double>(), below["pct"].get<double>() - 1e-9);
    }
  }
  EXPECT_EQ(tuning_rows, 2);
  EXPECT_EQ(reporting_rows, 2);
  ASSERT_EQ(json["fold_cells"].size(), 3u);  // one locomotion cell per style
  for (const auto& cell : json["fold_cells"]) {
    EXPECT_EQ(cell["category"], "locomotion");
    EXPECT_EQ(cell["half"], cell["fold"] == "normal" ? "reporting" : "tuning");
    ASSERT_EQ(cell["methods"].size(), 2u);
    EXPECT_EQ(cell["default_vs_mean"]["method"], "hierarchical");
  }
  ASSERT_EQ(json["above_mean"].size(), 2u);  // hierarchical in each half
  EXPECT_EQ(json["above_mean"][0]["cells"].get<int>() + json["above_mean"][1]["cells"].get<int>(), 3);
  std::map<std::string, double> reporting;
  for (const auto& clip : json["clips"]) {
    EXPECT_EQ(clip["half"], clip["fold"] == "normal" ? "reporting" : "tuning");
    if (clip["half"] == "reporting") reporting[clip["method"]] = clip["metrics"]["mpjpe_unkeyed_cm"].get<double>();
  }
  const RunResult plain =
      RunCli("-q eval --db " + db + " --contents run --folds normal --methods mean,hierarchical --json --split none");
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  const nlohmann::json unsplit = nlohmann::json::parse(plain.output);
  ASSERT_EQ(unsplit["clips"].size(), 2u);
  for (const auto& clip : unsplit["clips"])
    EXPECT_EQ(clip["metrics"]["mpjpe_unkeyed_cm"].get<double>(), reporting[clip["method"]]) << clip["method"];
}

// The table names both halves and their styles, shows intervals and the cells above mean, and
// with --by-fold a row per fold; a bad --split value is a usage error naming the allowed values,
// and so is --split with --against.
TEST(EvalCli, TablePrintsBothHalvesAndBadSplitIsAUsageError) {
  const std::string db = testing::FixturePath("default_db");
  const RunResult run = RunCli("-q eval --db " + db + " --contents run --methods mean,hierarchical --by-fold");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* expected : {"tuning half (2): happy, tired", "reporting half (1): normal", "tuning half: 2 folds",
                               "reporting half: 1 folds", "per fold: hierarchical above mean in", "2000 resamples"})
    EXPECT_NE(run.output.find(expected), std::string::npos) << expected << "\n" << run.output;
  EXPECT_NE(run.output.find(" ["), std::string::npos) << run.output;
  for (const char* fold : {"\nhappy ", "\ntired ", "\nnormal "})
    EXPECT_NE(run.output.find(fold), std::string::npos) << fold << "\n" << run.output;
  const RunResult bad = RunCli("eval --db " + db + " --split halves");
  EXPECT_EQ(bad.exit_code, 1) << bad.output;
  EXPECT_NE(bad.output.find("--split: unknown value 'halves' (allowed: none, tuning, reporting, both)"),
            std::string::npos)
      << bad.output;
  const RunResult fixed = RunCli("eval --db " + db + " --against " + db + " --split tuning");
  EXPECT_EQ(fixed.exit_code, 1) << fixed.output;
  EXPECT_NE(fixed.output.find("--split: not used with --against"), std::string::npos) << fixed.output;
}

// eval --against: every run clip of the default database tested against the whole default
// database, which holds it: covered everywhere, and the fill well below the mean pose (about
// 5.5 against 8.2 cm: 160 candidates are averaged, so even the clip itself is not copied).
TEST(EvalCli, AgainstAFixedDatabaseReportsCoverage) {
  const std::string db = testing::FixturePath("default_db");
  const RunResult run =
      RunCli("-q eval --db " + db + " --contents run --against " + db + " --methods mean,hierarchical --json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  const nlohmann::json json = nlohmann::json::parse(run.output);
  EXPECT_TRUE(json["protocol"]["loso"].is_null());
  EXPECT_EQ(json["protocol"]["against"][0], db);
  ASSERT_EQ(json["clips"].size(), 6u);  // 3 run clips x 2 methods
  for (const auto& clip : json["clips"]) EXPECT_EQ(clip["fold"], "against");
  double mean_cm = 0.0, hierarchical_cm = 0.0;
  for (const auto& row : json["summary"]) {
    if (row["category"] != "all") continue;
    if (row["method"] == "hierarchical") {
      hierarchical_cm = row["metrics"]["mpjpe_unkeyed_cm"].get<double>();
      EXPECT_EQ(row["coverage"]["poorly_covered_share"].get<double>(), 0.0);
      EXPECT_LT(row["coverage"]["median_unexplained"].get<double>(), 0.01);
    } else {
      mean_cm = row["metrics"]["mpjpe_unkeyed_cm"].get<double>();
    }
  }
  EXPECT_LT(hierarchical_cm, 0.8 * mean_cm);
}

// --coverage warn: the report carries the coverage of every fragment but blends nothing.
TEST(FillCli, CoverageReportWithoutBlending) {
  const std::string dir = testing::ScratchDir("fill_coverage");
  const RunResult run =
      RunCli("fill " + GlbSketch() + " -o " + dir + "/out.glb --coverage warn --report " + dir + "/fill.json");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("coverage: the nearest matches leave"), std::string::npos) << run.output;
  const nlohmann::json c = nlohmann::json::parse(ReadAll(dir + "/fill.json"))["coverage"];
  EXPECT_TRUE(c["measured"].get<bool>());
  EXPECT_TRUE(c["prior"].is_null());
  EXPECT_EQ(c["poor_share"].get<double>(), 0.04);
  ASSERT_GE(c["fragments"].size(), 10u);
  for (const auto& f : c["fragments"]) {
    EXPECT_EQ(f["prior_weight"].get<double>(), 0.0);
    EXPECT_EQ(f["texture_weight"].get<double>(), 0.0);
    EXPECT_GE(f["unexplained"].get<double>(), 0.0);
    EXPECT_GT(f["takes_ratio"].get<double>(), 0.0);
  }
  const RunResult bad = RunCli("fill " + GlbSketch() + " -o " + dir + "/bad.glb --coverage-poor 0.2 --coverage-none 0.1");
  EXPECT_EQ(bad.exit_code, 1) << bad.output;
  EXPECT_NE(bad.output.find("coverage.none_share"), std::string::npos) << bad.output;
  EXPECT_FALSE(fs::exists(dir + "/bad.glb"));
}

// Every named sketch (eval --scenario) scores on the default database's run clips with its keys
// exact; an unknown name is a usage error listing the known ones.
TEST(EvalCli, EveryScenarioKeepsItsKeys) {
  for (const char* scenario : {"legs8", "legs4", "legs16", "upper-body", "root", "root-arms"}) {
    const RunResult run = RunCli("-q eval --db " + testing::FixturePath("default_db") +
                                 " --contents run --folds happy --methods mean,hierarchical --json --scenario " +
                                 scenario);
    ASSERT_EQ(run.exit_code, 0) << scenario << ": " << run.output;
    const nlohmann::json json = nlohmann::json::parse(run.output);
    EXPECT_EQ(json["protocol"]["scenario"], scenario);
    ASSERT_EQ(json["clips"].size(), 2u) << scenario;
    for (const auto& clip : json["clips"]) {
      EXPECT_LT(clip["metrics"]["key_error_max_deg"].get<double>(), 0.01) << scenario;
      EXPECT_GT(clip["metrics"]["mpjpe_unkeyed_cm"].get<double>(), 0.0) << scenario;
    }
  }
  const RunResult bad = RunCli("eval --db " + testing::FixturePath("default_db") + " --scenario dance");
  EXPECT_EQ(bad.exit_code, 1) << bad.output;
  EXPECT_NE(bad.output.find("unknown scenario 'dance' (known: legs8, legs4"), std::string::npos) << bad.output;
}

// --mirror on reaches the fold databases: the held-out run clips score differently (the
// mean pose of a mirrored database is symmetric, so even `mean` moves), the test clip
// itself is not mirrored (one clip either way).
TEST(EvalCli, MirrorReachesTheFoldDatabases) {
  double unkeyed[2] = {0.0, 0.0};
  for (int on = 0; on < 2; ++on) {
    const RunResult run = RunCli("-q eval --db " + testing::FixturePath("default_db") +
                                 " --contents run --folds happy --methods mean --split none --json --mirror " +
                                 (on ? "on" : "off"));
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const nlohmann::json json = nlohmann::json::parse(run.output);
    ASSERT_EQ(json["clips"].size(), 1u);  // the run of the happy style, not mirrored
    for (const auto& clip : json["clips"]) unkeyed[on] += clip["metrics"]["mpjpe_unkeyed_cm"].get<double>();
  }
  EXPECT_GT(std::abs(unkeyed[1] - unkeyed[0]), 1e-3) << unkeyed[0] << " vs " << unkeyed[1];
}

TEST(EvalCli, UnknownMethodIsAUsageError) {
  const RunResult run = RunCli("eval --db " + testing::FixturePath("default_db") + " --methods magic");
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("unknown method 'magic'"), std::string::npos) << run.output;
}

TEST(FillCli, RejectsASketchWithoutAnimation) {
  const std::string out = testing::ScratchDir("fill_noanim") + "/out.glb";
  const RunResult run = RunCli("fill " + testing::FixturePath("gltf/quad_skin.glb") + " -o " + out);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find("no animation"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace mocapfill
