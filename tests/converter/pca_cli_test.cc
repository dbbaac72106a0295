// `mocapfill pca build / info / edit`: exit codes, messages, and edited glTF
// written under test-output/pca, which CI validates with the Khronos glTF-Validator.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>

#include "formats/motion_io.h"
#include "processing/core/rotation.h"
#include "tests/processing/pca_test_data.h"
#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::ReadAll;
using testing::RunCli;
using testing::RunResult;

namespace fs = std::filesystem;

std::string Quote(const std::string& s) { return "'" + s + "'"; }

// Builds walk.pca from six walks of other styles and converts walk_normal_001 to glb.
struct Workspace {
  std::string dir, model, input;
};

Workspace Prepare(const std::string& name) {
  Workspace w;
  w.dir = testing::ScratchDir(name);
  w.model = w.dir + "/walk.pca";
  w.input = w.dir + "/walk_normal.glb";
  std::vector<std::string> paths = testing::BandaiPathsExcept("walk", "normal");
  paths.resize(6);
  std::string db;
  for (const std::string& p : paths) db.append(" '").append(p).append("'");  // append: gcc 12 -Wrestrict false positive
  RunResult build = RunCli("pca build --db" + db + " -o " + Quote(w.model) + " --labels walk");
  EXPECT_EQ(build.exit_code, 0) << build.output;
  RunResult convert = RunCli("convert " + Quote(testing::BandaiClipPath("walk", "normal")) + " " + Quote(w.input));
  EXPECT_EQ(convert.exit_code, 0) << convert.output;
  return w;
}

TEST(PcaCli, BuildThenInfoReportsComponentsAndVariance) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Workspace w = Prepare("pca_cli_info");
  RunResult info = RunCli("pca info --json " + Quote(w.model));
  ASSERT_EQ(info.exit_code, 0) << info.output;
  const nlohmann::json json = nlohmann::json::parse(info.output);
  EXPECT_EQ(json["kind"], "pose");
  EXPECT_EQ(json["joints"], 22);
  EXPECT_EQ(json["root_joint"], "Hips");
  const int k = json["components"];
  EXPECT_GE(k, 1);
  EXPECT_LE(k, 30);
  EXPECT_GE(json["explained_variance"].get<double>(), 0.95);
  EXPECT_NEAR(json["compression_ratio"].get<double>(), 70.0 / k, 1e-12);
  EXPECT_EQ(json["cumulative_explained_variance"].size(), static_cast<size_t>(k));
  EXPECT_EQ(json["clips"], 6);
  RunResult text = RunCli("pca info " + Quote(w.model));
  EXPECT_EQ(text.exit_code, 0);
  EXPECT_NE(text.output.find("compression ratio"), std::string::npos) << text.output;
}

TEST(PcaCli, EditWritesValidGltfAndZeroDialsKeepTheMotion) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Workspace w = Prepare("pca_cli_edit");
  const std::string out_dir = testing::TestOutputDir("pca");
  const std::string edited = out_dir + "/walk_normal_c1p2_c3m1.glb", same = out_dir + "/walk_normal_zero.glb";
  RunResult edit = RunCli("pca edit " + Quote(w.input) + " -o " + Quote(edited) + " --model " + Quote(w.model) +
                          " --component 1=+2.0 --component 3=-1.0");
  ASSERT_EQ(edit.exit_code, 0) << edit.output;
  RunResult zero = RunCli("pca edit " + Quote(w.input) + " -o " + Quote(same) + " --model " + Quote(w.model) +
                          " --component 1=0");
  ASSERT_EQ(zero.exit_code, 0) << zero.output;
  Result<Scene> in = ImportFile(w.input), out = ImportFile(edited), identity = ImportFile(same);
  ASSERT_TRUE(in.ok() && out.ok() && identity.ok());
  const MotionClip &a = in->clips[0], &b = out->clips[0], &c = identity->clips[0];
  ASSERT_EQ(a.num_frames, b.num_frames);
  ASSERT_EQ(a.num_frames, c.num_frames);
  double moved_deg = 0.0, kept_deg = 0.0;
  for (int f = 0; f < a.num_frames; ++f)
    for (int j = 0; j < a.num_joints; ++j) {
      moved_deg = std::max(moved_deg, GeodesicAngle(a.rotation(f, j), b.rotation(f, j)) * kDegPerRad);
      kept_deg = std::max(kept_deg, GeodesicAngle(a.rotation(f, j), c.rotation(f, j)) * kDegPerRad);
    }
  EXPECT_GT(moved_deg, 5.0);   // two standard deviations of the first component are visible
  EXPECT_LT(kept_deg, 1e-3);   // float32 glTF storage only
}

TEST(PcaCli, BadInputsGiveDocumentedExitCodesAndNoOutput) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Workspace w = Prepare("pca_cli_errors");
  const std::string out = w.dir + "/out.glb";
  RunResult range = RunCli("pca edit " + Quote(w.input) + " -o " + Quote(out) + " --model " + Quote(w.model) +
                           " --component 99=1");
  EXPECT_EQ(range.exit_code, 1);
  EXPECT_NE(range.output.find("out of range"), std::string::npos) << range.output;
  RunResult syntax = RunCli("pca edit " + Quote(w.input) + " -o " + Quote(out) + " --model " + Quote(w.model) +
                            " --component 2:1");
  EXPECT_EQ(syntax.exit_code, 1);
  EXPECT_NE(syntax.output.find("--component: \"2:1\": expected <key>=<value>, e.g. 1=+2.0"), std::string::npos) << syntax.output;
  const std::string truncated = w.dir + "/truncated.pca";
  fs::copy_file(w.model, truncated);
  fs::resize_file(truncated, 100);
  RunResult bad = RunCli("pca info " + Quote(truncated));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.output.find("truncated"), std::string::npos) << bad.output;
  RunResult edit_bad = RunCli("pca edit " + Quote(w.input) + " -o " + Quote(out) + " --model " + Quote(truncated));
  EXPECT_EQ(edit_bad.exit_code, 2);
  RunResult labels = RunCli("pca build --db " + Quote(testing::BandaiClipPath("walk", "angry")) + " -o " +
                            Quote(w.dir + "/none.pca") + " --labels dance");
  EXPECT_EQ(labels.exit_code, 1);
  EXPECT_NE(labels.output.find("dance"), std::string::npos) << labels.output;
  RunResult extension = RunCli("pca build --db " + Quote(testing::BandaiClipPath("walk", "angry")) + " -o " +
                               Quote(w.dir + "/model.bin"));
  EXPECT_EQ(extension.exit_code, 1);
  EXPECT_FALSE(fs::exists(out));
  EXPECT_FALSE(fs::exists(w.dir + "/none.pca"));
  EXPECT_FALSE(fs::exists(w.dir + "/model.bin"));
}

}  // namespace
}  // namespace mocapfill
