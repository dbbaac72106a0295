// `mocapfill run` end to end: the shipped example pipelines on the shipped fixtures (glTF
// under test-output/pipeline for the validator), and every kind of bad pipeline rejected with
// exit 1, a message naming the node and option, and nothing written.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "formats/motion_io.h"
#include "processing/core/rotation.h"
#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::ReadAll;
using testing::RunCli;
using testing::RunResult;

namespace fs = std::filesystem;

constexpr double kKeyToleranceDeg = 0.5;  // keyed joints hold their keys
constexpr double kConvertToleranceRad = 1e-5;  // glTF stores float rotations

std::string Example(const std::string& name) { return testing::FixturePath("pipelines/" + name); }

std::string OutPath(const std::string& name) { return testing::TestOutputDir("pipeline") + "/" + name; }

// Runs a shipped pipeline with its export redirected under test-output.
Scene RunExample(const std::string& pipeline, const std::string& out_name, const std::string& extra = "") {
  const std::string out = OutPath(out_name);
  fs::remove(out);
  const RunResult run = RunCli("run " + Example(pipeline) + " --set out.path=" + out + " " + extra);
  EXPECT_EQ(run.exit_code, 0) << run.output;
  Result<Scene> scene = ImportFile(out);
  EXPECT_TRUE(scene.ok()) << (scene.ok() ? "" : scene.status().message());
  return scene.ok() ? std::move(scene).value() : Scene{};
}

double AngleDeg(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) { return a.angularDistance(b) * kDegPerRad; }

// Mean angle between the clips' rotations over every joint and frame both have.
double MeanAngleDeg(const MotionClip& a, const MotionClip& b) {
  double sum = 0.0;
  const int frames = std::min(a.num_frames, b.num_frames);
  for (int f = 0; f < frames; ++f)
    for (int j = 0; j < a.num_joints; ++j) sum += AngleDeg(a.rotation(f, j), b.rotation(f, j));
  return sum / (frames * a.num_joints);
}

// Mean angle of the sketch's keyed joints at their key frames (same rate).
double KeyErrorDeg(const Scene& sketch, const MotionClip& out) {
  const MotionClip& s = sketch.clips.at(0);
  double sum = 0.0;
  int n = 0;
  for (int j = 0; j < s.num_joints; ++j)
    for (int f : s.keys[j].rotation_frames) {
      if (f >= out.num_frames) continue;
      sum += AngleDeg(s.rotation(f, j), out.rotation(f, j));
      ++n;
    }
  EXPECT_GT(n, 0);
  return n ? sum / n : 1e9;
}

Scene Sketch() {
  Result<Scene> sketch = ImportFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  EXPECT_TRUE(sketch.ok());
  return sketch.ok() ? std::move(sketch).value() : Scene{};
}

TEST(PipelineExamples, ConvertWritesTheBvhAsGltf) {
  const Scene out = RunExample("convert.json", "convert_cmu_01_01.glb");
  ImportOptions cmu;
  cmu.unit = "cmu";
  Result<Scene> bvh = ImportFile(testing::FixturePath("bvh/cmu_01_01_short.bvh"), cmu);
  ASSERT_TRUE(bvh.ok());
  ASSERT_EQ(out.clips.size(), 1u);
  ASSERT_EQ(out.skeleton.num_joints(), bvh->skeleton.num_joints());
  ASSERT_EQ(out.clips[0].num_frames, bvh->clips[0].num_frames);
  double worst = 0.0;
  for (size_t i = 0; i < out.clips[0].rotations.size(); ++i)
    worst = std::max(worst, out.clips[0].rotations[i].angularDistance(bvh->clips[0].rotations[i]));
  EXPECT_LT(worst, kConvertToleranceRad);
  // Root translation in metres (cmu unit converted): frame 0 hips of subject 01 at ~0.9-1 m height.
  EXPECT_NEAR(out.clips[0].translation(0, 0).y(), bvh->clips[0].translation(0, 0).y(), 1e-5);
}

TEST(PipelineExamples, FilterChangesTheWalkButKeepsItsFrames) {
  const Scene out = RunExample("filter.json", "filter_walk.glb");
  Result<Scene> walk = ImportFile(testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"));
  ASSERT_TRUE(walk.ok());
  ASSERT_EQ(out.clips.size(), 1u);
  EXPECT_EQ(out.clips[0].num_frames, walk->clips[0].num_frames);
  // Gains 1.5 on bands 1-2 move the walk by a visible amount on average (about 0.5 deg).
  EXPECT_GT(MeanAngleDeg(out.clips[0], walk->clips[0]), 0.1);
  EXPECT_LT(MeanAngleDeg(out.clips[0], walk->clips[0]), 5.0);
}

TEST(PipelineExamples, FillDefaultKeepsTheKeysAndReportsEveryNode) {
  const std::string report = testing::ScratchDir("pipeline_report") + "/run.json";
  const Scene out = RunExample("fill_default.json", "fill_default.glb", "--report " + report);
  const Scene sketch = Sketch();
  ASSERT_EQ(out.skeleton.num_joints(), sketch.skeleton.num_joints());
  ASSERT_EQ(out.clips.size(), 1u);
  EXPECT_LT(KeyErrorDeg(sketch, out.clips[0]), kKeyToleranceDeg);
  std::ifstream in(report);
  const nlohmann::json json = nlohmann::json::parse(in);
  EXPECT_TRUE(json["ok"].get<bool>());
  ASSERT_EQ(json["nodes"].size(), 4u);
  std::vector<std::string> ids;
  double sum_s = 0.0;
  for (const auto& node : json["nodes"]) {
    ids.push_back(node["id"]);
    EXPECT_GE(node["seconds"].get<double>(), 0.0);
    sum_s += node["seconds"].get<double>();
  }
  EXPECT_EQ(ids, (std::vector<std::string>{"sketch", "db", "fill", "out"}));
  EXPECT_LE(sum_s, json["total_seconds"].get<double>() + 1e-6);
}

TEST(PipelineExamples, SetOverridesTheFillMethod) {
  const Scene hierarchical = RunExample("fill_default.json", "fill_default_h.glb");
  const Scene mean = RunExample("fill_default.json", "fill_default_mean.glb", "--set fill.method=mean");
  ASSERT_EQ(mean.clips.size(), 1u);
  ASSERT_EQ(hierarchical.clips.size(), 1u);
  // Keys hold either way; the synthesised upper body differs between the methods.
  EXPECT_LT(KeyErrorDeg(Sketch(), mean.clips[0]), kKeyToleranceDeg);
  EXPECT_GT(MeanAngleDeg(mean.clips[0], hierarchical.clips[0]), 0.5);
}

TEST(PipelineExamples, PcaEditMovesTheFilledWalk) {
  const Scene filled = RunExample("fill_default.json", "fill_default_for_edit.glb");
  const Scene edited = RunExample("fill_pca_edit.json", "fill_pca_edit.glb");
  ASSERT_EQ(edited.clips.size(), 1u);
  ASSERT_EQ(edited.clips[0].num_frames, filled.clips[0].num_frames);
  // +1.5 sigma on the first component of the walks: a posture change of degrees, not noise.
  EXPECT_GT(MeanAngleDeg(edited.clips[0], filled.clips[0]), 0.5);
}

TEST(PipelineExamples, PcaFitGuidedByFragmentsAndTextured) {
  const Scene out = RunExample("fill_pca_fit_texture.json", "fill_pca_fit_texture.glb");
  const Scene sketch = Sketch();
  ASSERT_EQ(out.clips.size(), 1u);
  ASSERT_EQ(out.skeleton.num_joints(), sketch.skeleton.num_joints());
  // The full-pose fit holds the keys exactly and texturing re-pins them.
  EXPECT_LT(KeyErrorDeg(sketch, out.clips[0]), kKeyToleranceDeg);
  // Without re-pinning the fragments' high bands move the keyed joints at their keys too
  // (about 2.8 deg mean), which shows the texture node did add detail.
  const Scene loose = RunExample("fill_pca_fit_texture.json", "fill_pca_fit_texture_loose.glb",
                                 "--set detail.repin_keys=false");
  ASSERT_EQ(loose.clips.size(), 1u);
  EXPECT_GT(KeyErrorDeg(sketch, loose.clips[0]), 1.0);
  EXPECT_GT(MeanAngleDeg(loose.clips[0], out.clips[0]), 0.1);
}

TEST(PipelineExamples, HybridFillTakesTheModelPort) {
  const Scene hybrid = RunExample("fill_hybrid.json", "fill_hybrid.glb");
  const Scene hierarchical = RunExample("fill_default.json", "fill_default_for_hybrid.glb");
  ASSERT_EQ(hybrid.clips.size(), 1u);
  ASSERT_EQ(hierarchical.clips.size(), 1u);
  EXPECT_LT(KeyErrorDeg(Sketch(), hybrid.clips[0]), kKeyToleranceDeg);  // keys re-pinned
  EXPECT_GT(MeanAngleDeg(hybrid.clips[0], hierarchical.clips[0]), 0.1);  // the PCA stage did act
}

TEST(PipelineRun, DryRunPrintsThePlanAndWritesNothing) {
  const std::string out = testing::ScratchDir("pipeline_dry") + "/never.glb";
  const RunResult run = RunCli("run " + Example("fill_pca_fit_texture.json") + " --dry-run --set out.path=" + out);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_NE(run.output.find("7 nodes, valid"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("5. fit (pca_fit) -> motion"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("input  guide <- fill"), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("option max_iterations = 50"), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(out));
}

TEST(PipelineRun, HelpCarriesExamplesAndNoPipelineIsAUsageError) {
  const RunResult help = RunCli("run --help");
  ASSERT_EQ(help.exit_code, 0) << help.output;
  EXPECT_NE(help.output.find("Examples:"), std::string::npos) << help.output;
  const RunResult none = RunCli("run");
  EXPECT_EQ(none.exit_code, 1) << none.output;
  EXPECT_NE(none.output.find("error: give a pipeline file (or --list-nodes)"), std::string::npos) << none.output;
}

TEST(PipelineRun, ListNodesDocumentsEveryType) {
  const RunResult run = RunCli("run --list-nodes");
  ASSERT_EQ(run.exit_code, 0) << run.output;
  for (const char* type : {"import:", "database:", "pca_model:", "export:", "fill:", "filter:", "texture:",
                           "pca_build:", "pca_fit:", "pca_edit:"})
    EXPECT_NE(("\n" + run.output).find(std::string("\n") + type), std::string::npos) << type;
  EXPECT_NE(run.output.find("option fragment_band_hz (number, default 1, Hz, >= 0.01 and <= 100; flag --fragment-hz)"),
            std::string::npos)
      << run.output;
}

// A small valid pipeline (import -> filter -> export) written to a scratch folder, with one
// node edited by `edit` to break it.
struct BadPipeline {
  std::string dir, path, out;
};

BadPipeline Write(const std::string& name, const std::function<void(nlohmann::json&)>& edit) {
  BadPipeline p;
  p.dir = testing::ScratchDir("pipeline_bad_" + name);
  p.path = p.dir + "/pipeline.json";
  p.out = p.dir + "/out.glb";
  nlohmann::json json = {
      {"version", 1},
      {"nodes",
       {{{"id", "walk"}, {"type", "import"}, {"options", {{"path", testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh")}}}},
        {{"id", "eq"}, {"type", "filter"}, {"inputs", {{"motion", "walk"}}}, {"options", {{"gains", {1.0, 1.2}}}}},
        {{"id", "out"}, {"type", "export"}, {"inputs", {{"motion", "eq"}}}, {"options", {{"path", "out.glb"}}}}}}};
  edit(json);
  std::ofstream(p.path) << json.dump(2);
  return p;
}

void ExpectRejected(const BadPipeline& p, int exit_code, const std::string& message, const std::string& extra = "") {
  const RunResult run = RunCli("run " + p.path + " " + extra);
  EXPECT_EQ(run.exit_code, exit_code) << run.output;
  EXPECT_NE(run.output.find("error: " + p.path + ": " + message), std::string::npos) << run.output;
  EXPECT_FALSE(fs::exists(p.out)) << "output written by a rejected pipeline";
}

TEST(PipelineRun, TheValidPipelineRuns) {
  const BadPipeline p = Write("none", [](nlohmann::json&) {});
  const RunResult run = RunCli("run " + p.path);
  ASSERT_EQ(run.exit_code, 0) << run.output;
  EXPECT_TRUE(fs::exists(p.out));  // relative to the pipeline's folder
}

TEST(PipelineRun, RejectsUnknownNodeType) {
  ExpectRejected(Write("type", [](nlohmann::json& j) { j["nodes"][1]["type"] = "equalize"; }), 1,
                 "node \"eq\" (equalize): unknown node type \"equalize\" (known: ");
}

TEST(PipelineRun, RejectsUnknownOption) {
  ExpectRejected(Write("option", [](nlohmann::json& j) { j["nodes"][1]["options"]["gain"] = 2; }), 1,
                 "node \"eq\" (filter): option \"gain\": unknown option (filter has: gains, residual_gain, joints, levels, periodic)");
}

TEST(PipelineRun, RejectsWrongOptionType) {
  ExpectRejected(Write("option_type", [](nlohmann::json& j) { j["nodes"][1]["options"]["gains"] = "1.5"; }), 1,
                 "node \"eq\" (filter): option \"gains\": expected an array, got \"1.5\"");
}

TEST(PipelineRun, RejectsOutOfRangeValue) {
  ExpectRejected(Write("range", [](nlohmann::json& j) { j["nodes"][1]["options"]["levels"] = 40; }), 1,
                 "node \"eq\" (filter): option \"levels\": expected an integer in [0, 16], got 40");
}

TEST(PipelineRun, RejectsBadFillMethodWithTheKnownMethods) {
  ExpectRejected(Write("method",
                       [](nlohmann::json& j) {
                         j["nodes"].push_back({{"id", "db"}, {"type", "database"}});
                         j["nodes"].push_back({{"id", "fill"},
                                               {"type", "fill"},
                                               {"inputs", {{"sketch", "walk"}, {"database", "db"}}},
                                               {"options", {{"method", "foo"}}}});
                       }),
                 1, "node \"fill\" (fill): option \"method\": unknown method 'foo' (expected hierarchical, fragment, nn, mean");
}

TEST(PipelineRun, RejectsMissingInputPort) {
  ExpectRejected(Write("port", [](nlohmann::json& j) { j["nodes"][2].erase("inputs"); }), 1,
                 "node \"out\" (export): input \"motion\": missing (a motion is required");
}

TEST(PipelineRun, RejectsInputNamingAnUnknownNode) {
  ExpectRejected(Write("producer", [](nlohmann::json& j) { j["nodes"][2]["inputs"]["motion"] = "qe"; }), 1,
                 "node \"out\" (export): input \"motion\": no node \"qe\" in the pipeline");
}

TEST(PipelineRun, RejectsWrongPortType) {
  ExpectRejected(Write("port_type",
                       [](nlohmann::json& j) {
                         j["nodes"].push_back({{"id", "db"}, {"type", "database"}});
                         j["nodes"][1]["inputs"]["motion"] = "db";
                       }),
                 1, "node \"eq\" (filter): input \"motion\": expects a motion, node \"db\" (database) gives a database");
}

TEST(PipelineRun, RejectsDuplicateId) {
  ExpectRejected(Write("duplicate", [](nlohmann::json& j) { j["nodes"][1]["id"] = "walk"; }), 1,
                 "node \"walk\" (filter): \"id\": duplicate id");
}

TEST(PipelineRun, RejectsCycles) {
  ExpectRejected(Write("cycle",
                       [](nlohmann::json& j) {
                         j["nodes"][1]["inputs"]["motion"] = "eq2";
                         j["nodes"].push_back({{"id", "eq2"}, {"type", "filter"}, {"inputs", {{"motion", "eq"}}}});
                       }),
                 1, "node \"eq\" (filter): is part of a cycle");
  ExpectRejected(Write("cycle_downstream",
                       [](nlohmann::json& j) {
                         j["nodes"][1]["inputs"]["motion"] = "eq2";
                         j["nodes"].push_back({{"id", "eq2"}, {"type", "filter"}, {"inputs", {{"motion", "eq"}}}});
                       }),
                 1, "node \"out\" (export): depends on a cycle");
}

TEST(PipelineRun, RejectsInvalidJsonAndBadOverrides) {
  const BadPipeline p = Write("json", [](nlohmann::json&) {});
  std::ofstream(p.path) << "{\"version\": 1, \"nodes\": [";
  const RunResult run = RunCli("run " + p.path);
  EXPECT_EQ(run.exit_code, 1) << run.output;
  EXPECT_NE(run.output.find("error: " + p.path + ": invalid JSON: parse error at line 1"), std::string::npos) << run.output;
  const BadPipeline q = Write("set", [](nlohmann::json&) {});
  ExpectRejected(q, 1, "--set \"nope.x=1\": no node \"nope\" in the pipeline", "--set eq.levels=99 --set nope.x=1");
  ExpectRejected(q, 1, "node \"eq\" (filter): option \"levels\": expected an integer in [0, 16], got 99", "--set eq.levels=99");
}

TEST(PipelineRun, MissingInputFileIsExit2AndWritesNothing) {
  ExpectRejected(Write("missing", [](nlohmann::json& j) { j["nodes"][0]["options"]["path"] = "absent.bvh"; }), 2,
                 "node \"walk\" (import): ");
}

TEST(PipelineRun, RefusesToOverwriteAnInputWithExit4) {
  const BadPipeline p = Write("overwrite", [](nlohmann::json& j) {
    j["nodes"][0]["options"]["path"] = "in.glb";
    j["nodes"][2]["options"]["path"] = "in.glb";
  });
  fs::copy_file(testing::FixturePath("sketches/walk_proud_002_legs8.glb"), p.dir + "/in.glb");
  const auto before = fs::file_size(p.dir + "/in.glb");
  const RunResult run = RunCli("run " + p.path);
  EXPECT_EQ(run.exit_code, 4) << run.output;
  EXPECT_NE(run.output.find("node \"out\" (export): option \"path\": refusing to overwrite"), std::string::npos) << run.output;
  EXPECT_EQ(fs::file_size(p.dir + "/in.glb"), before);
}

}  // namespace
}  // namespace mocapfill
