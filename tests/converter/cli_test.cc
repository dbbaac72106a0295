// CLI contract tests: run the built mocapfill executable and check exit codes, messages,
// and that failures leave no output file and never touch an input.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sys/wait.h>

#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

namespace fs = std::filesystem;

struct RunResult {
  int exit_code = -1;
  std::string output;  // stdout and stderr together
};

// Runs `exe args` with `env` ("NAME=value ...", may be empty) in its environment.
RunResult RunProgram(const std::string& env, const std::string& exe, const std::string& args) {
  RunResult result;
  const std::string command = env + " " + exe + " " + args + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer;
  size_t n;
  while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

RunResult RunCli(const std::string& args) { return RunProgram("", testing::MocapfillExe(), args); }

std::string Quote(const std::string& s) { return "'" + s + "'"; }

std::vector<std::string> FixtureBvhFiles() { return testing::FixtureFiles("bvh", ".bvh"); }

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

TEST(Cli, VersionAndHelpForEveryVerb) {
  RunResult version = RunCli("--version");
  EXPECT_EQ(version.exit_code, 0);
  EXPECT_NE(version.output.find("mocapfill "), std::string::npos);
  for (const char* verb : {"convert", "inspect", "db build", "db info", "filter", "analyze", "fill", "eval",
                           "pca build", "pca info", "pca edit"}) {
    RunResult help = RunCli(std::string(verb) + " --help");
    EXPECT_EQ(help.exit_code, 0) << verb;
    EXPECT_NE(help.output.find("Example"), std::string::npos) << verb << ": " << help.output;
  }
  EXPECT_NE(RunCli("--help").output.find("Exit codes"), std::string::npos);
}

TEST(Cli, UsageErrorsExitWithOne) {
  EXPECT_EQ(RunCli("").exit_code, 1);
  EXPECT_EQ(RunCli("frobnicate").exit_code, 1);
  EXPECT_EQ(RunCli("convert").exit_code, 1);
  EXPECT_EQ(RunCli("convert --unit parsec a.bvh b.glb").exit_code, 1);
  const std::string dir = testing::ScratchDir("cli_usage");
  EXPECT_EQ(RunCli("convert " + Quote(FixtureBvhFiles().at(0)) + " " + Quote(dir + "/out.obj")).exit_code, 1);
  EXPECT_FALSE(fs::exists(dir + "/out.obj"));
}

// --no-skin, --skeleton-mesh and --bvh-layout: what each writes, and usage errors (exit 1,
// nothing written) for contradicting or unknown values.
TEST(Cli, SkeletonAndBvhLayoutFlags) {
  const std::string bvh = Quote(testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"));
  const std::string dir = testing::TestOutputDir("cli_skeleton_flags");
  const auto json_of = [](const std::string& glb) {
    const std::string bytes = ReadAll(glb);
    uint32_t length = 0;
    std::memcpy(&length, bytes.data() + 12, 4);
    return nlohmann::json::parse(bytes.substr(20, length));
  };
  ASSERT_EQ(RunCli("convert " + bvh + " " + Quote(dir + "/skin.glb")).exit_code, 0);
  ASSERT_EQ(RunCli("convert " + bvh + " " + Quote(dir + "/mesh.glb") + " --skeleton-mesh").exit_code, 0);
  ASSERT_EQ(RunCli("convert " + bvh + " " + Quote(dir + "/bare.glb") + " --no-skin").exit_code, 0);
  const nlohmann::json skin = json_of(dir + "/skin.glb"), mesh = json_of(dir + "/mesh.glb"),
                       bare = json_of(dir + "/bare.glb");
  EXPECT_EQ(skin["skins"][0]["joints"].size(), skin["nodes"].size());
  EXPECT_FALSE(skin.contains("meshes"));
  EXPECT_EQ(mesh["meshes"].size(), 1u);
  EXPECT_EQ(mesh["nodes"].back()["skin"], 0);
  EXPECT_FALSE(bare.contains("skins"));
  // The stick figure read back is left out: converting mesh.glb again gives one, not two.
  ASSERT_EQ(RunCli("convert " + Quote(dir + "/mesh.glb") + " " + Quote(dir + "/mesh_again.glb") + " --skeleton-mesh")
                .exit_code,
            0);
  EXPECT_EQ(json_of(dir + "/mesh_again.glb")["meshes"].size(), 1u);
  EXPECT_EQ(json_of(dir + "/mesh_again.glb")["nodes"].size(), mesh["nodes"].size());

  const std::string scratch = testing::ScratchDir("cli_skeleton_flags");
  const RunResult both = RunCli("convert " + bvh + " " + Quote(scratch + "/x.glb") + " --no-skin --skeleton-mesh");
  EXPECT_EQ(both.exit_code, 1) << both.output;
  EXPECT_NE(both.output.find("excludes"), std::string::npos) << both.output;
  EXPECT_EQ(RunCli("convert " + bvh + " " + Quote(scratch + "/x.bvh") + " --bvh-layout three").exit_code, 1);
  EXPECT_FALSE(fs::exists(scratch + "/x.glb") || fs::exists(scratch + "/x.bvh"));
  ASSERT_EQ(RunCli("convert " + bvh + " " + Quote(scratch + "/standard.bvh") + " --bvh-layout standard").exit_code, 0);
  const std::string standard = ReadAll(scratch + "/standard.bvh");
  EXPECT_NE(standard.find("JOINT Hips\n\t{\n\t\tOFFSET 0 0 0\n\t\tCHANNELS 6"), std::string::npos);
}

TEST(Cli, MissingInputExitsWithTwoAndWritesNothing) {
  const std::string dir = testing::ScratchDir("cli_missing");
  RunResult r = RunCli("convert " + Quote(dir + "/nope.bvh") + " " + Quote(dir + "/out.glb"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("nope.bvh"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/out.glb"));
}

TEST(Cli, BadInputsExitWithTwoNameTheFileAndLeaveNoOutput) {
  const std::string dir = testing::ScratchDir("cli_bad");
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(testing::FixturePath("bad"))) {
    const std::string in = entry.path().string();
    const std::string out = dir + "/" + entry.path().stem().string() + ".glb";
    RunResult r = RunCli("convert " + Quote(in) + " " + Quote(out));
    EXPECT_EQ(r.exit_code, 2) << in << ": " << r.output;
    EXPECT_NE(r.output.find(entry.path().filename().string()), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("error: "), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(out)) << out;
    ++checked;
  }
  EXPECT_GE(checked, 5);
  for (const auto& entry : fs::directory_iterator(dir)) ADD_FAILURE() << "left behind: " << entry.path();
}

TEST(Cli, TruncatedBvhMessageNamesTheLine) {
  RunResult r = RunCli("inspect " + Quote(testing::FixturePath("bad/truncated.bvh")));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.output.find("truncated.bvh:"), std::string::npos) << r.output;
}

TEST(Cli, FailedConversionKeepsAnExistingOutputUntouched) {
  const std::string dir = testing::ScratchDir("cli_keep");
  const std::string out = dir + "/out.glb";
  { std::ofstream(out) << "previous content"; }
  RunResult r = RunCli("convert " + Quote(testing::FixturePath("bad/truncated.bvh")) + " " + Quote(out));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(ReadAll(out), "previous content");
}

TEST(Cli, RefusesToOverwriteAnInput) {
  const std::string dir = testing::ScratchDir("cli_overwrite");
  const std::string in = dir + "/clip.bvh";
  fs::copy_file(FixtureBvhFiles().at(0), in);
  const std::string before = ReadAll(in);
  RunResult r = RunCli("convert " + Quote(in) + " " + Quote(in));
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("refusing to overwrite"), std::string::npos) << r.output;
  EXPECT_EQ(ReadAll(in), before);
  // The same file reached through another path is caught too.
  RunResult r2 = RunCli("convert " + Quote(in) + " -o " + Quote(dir) + " --format bvh");
  EXPECT_EQ(r2.exit_code, 4) << r2.output;
  EXPECT_EQ(ReadAll(in), before);
  // An input that cannot be identified (it does not exist) is still known by its path.
  const std::string missing = dir + "/missing.bvh";
  RunResult r3 = RunCli("convert " + Quote(missing) + " " + Quote(dir + "/./missing.bvh"));
  EXPECT_EQ(r3.exit_code, 4) << r3.output;
  EXPECT_NE(r3.output.find("refusing to overwrite"), std::string::npos) << r3.output;
  EXPECT_FALSE(fs::exists(missing));
}

// A batch into `dir` wrote a .glb for each input, named after it.
void ExpectGlbPerInput(const std::string& dir, const std::vector<std::string>& inputs) {
  for (const std::string& in : inputs) {
    const std::string out = dir + "/" + fs::path(in).stem().string() + ".glb";
    EXPECT_TRUE(fs::exists(out)) << out;
    EXPECT_EQ(ReadAll(out).substr(0, 4), "glTF") << out;
  }
}

TEST(Cli, BatchConvertWritesOneValidOutputPerInput) {
  const std::string dir = testing::TestOutputDir("cli_batch");
  std::string args = "convert";
  const auto inputs = FixtureBvhFiles();
  for (const std::string& in : inputs) args.append(" ").append(Quote(in));
  RunResult r = RunCli(args + " -o " + Quote(dir) + " -j 2");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  ExpectGlbPerInput(dir, inputs);
}

// A batch with bad inputs among good ones (bad ones first, so the work has to go on past
// them): every good input converted, every bad one named with its reason, nothing written
// for the bad ones, a count at the end, exit 2.
TEST(Cli, BatchWithBadInputsConvertsTheGoodOnesAndReportsEveryBadOne) {
  const std::string dir = testing::ScratchDir("cli_batch_mixed");
  std::vector<std::string> bad;
  for (const char* name : {"garbage.bvh", "missing_brace.bvh", "nan_value.bvh", "unknown_channel.bvh",
                           "wrong_channel_count.bvh"})
    bad.push_back(testing::FixturePath(std::string("bad/") + name));
  const std::vector<std::string> good = FixtureBvhFiles();
  std::string args = "convert";
  for (const std::string& in : bad) args.append(" ").append(Quote(in));
  for (const std::string& in : good) args.append(" ").append(Quote(in));
  RunResult r = RunCli(args + " -o " + Quote(dir) + " -j 2");
  EXPECT_EQ(r.exit_code, 2) << r.output;
  ExpectGlbPerInput(dir, good);
  for (const std::string& in : bad) {
    EXPECT_NE(r.output.find("error: " + in), std::string::npos) << in << "\n" << r.output;
    EXPECT_FALSE(fs::exists(dir + "/" + fs::path(in).stem().string() + ".glb")) << in;
  }
  const std::string summary = "error: " + std::to_string(bad.size()) + " of " + std::to_string(bad.size() + good.size()) +
                              " inputs failed; " + std::to_string(good.size()) + " converted";
  EXPECT_NE(r.output.find(summary), std::string::npos) << r.output;
  size_t files = 0;
  for (const auto& entry : fs::directory_iterator(dir)) files += entry.is_regular_file();
  EXPECT_EQ(files, good.size()) << "only the good inputs' outputs, no temporary files";
}

TEST(Cli, ConvertIsDeterministic) {
  const std::string dir = testing::ScratchDir("cli_determinism");
  const std::string in = FixtureBvhFiles().at(0);
  ASSERT_EQ(RunCli("convert " + Quote(in) + " " + Quote(dir + "/a.glb")).exit_code, 0);
  ASSERT_EQ(RunCli("convert " + Quote(in) + " " + Quote(dir + "/b.glb")).exit_code, 0);
  EXPECT_EQ(ReadAll(dir + "/a.glb"), ReadAll(dir + "/b.glb"));
}

TEST(Cli, InspectJsonDescribesTheClip) {
  for (const std::string& in : FixtureBvhFiles()) {
    RunResult r = RunCli("inspect --json " + Quote(in));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto json = nlohmann::json::parse(r.output);
    EXPECT_EQ(json["format"], "bvh");
    EXPECT_GT(json["skeleton"]["joints"].get<int>(), 1);
    ASSERT_EQ(json["clips"].size(), 1u);
    EXPECT_GT(json["clips"][0]["frames"].get<int>(), 1);
    EXPECT_GT(json["clips"][0]["rate_hz"].get<double>(), 0.0);
    EXPECT_NEAR(json["clips"][0]["duration_s"].get<double>(),
                (json["clips"][0]["frames"].get<int>() - 1) / json["clips"][0]["rate_hz"].get<double>(), 1e-9);
  }
}

// FBX is read by the Assimp plug-in (mocapfill_assimp.so), loaded only for Assimp formats.
TEST(Cli, FbxIsReadThroughTheAssimpPlugin) {
  const std::string fbx = testing::FixturePath("fbx/animation_with_skeleton.fbx");
  RunResult r = RunCli("inspect --json " + Quote(fbx));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const auto json = nlohmann::json::parse(r.output);
  EXPECT_EQ(json["format"], "fbx");
  EXPECT_GT(json["skeleton"]["joints"].get<int>(), 1);
  const std::string dir = testing::ScratchDir("cli_fbx");
  ASSERT_EQ(RunCli("convert " + Quote(fbx) + " " + Quote(dir + "/out.glb")).exit_code, 0);
  EXPECT_EQ(ReadAll(dir + "/out.glb").substr(0, 4), "glTF");
}

TEST(Cli, MissingAssimpPluginIsAClearErrorAndBvhNeedsNone) {
  const std::string dir = testing::ScratchDir("cli_no_plugin");
  const std::string env = "MOCAPFILL_ASSIMP_MODULE=" + Quote(dir + "/missing.so");
  RunResult r = RunProgram(env, testing::MocapfillExe(),
                           "convert " + Quote(testing::FixturePath("fbx/pivot_chain.fbx")) + " " + Quote(dir + "/out.glb"));
  EXPECT_EQ(r.exit_code, 2) << r.output;
  EXPECT_NE(r.output.find("pivot_chain.fbx"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("mocapfill_assimp.so"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(dir + "/missing.so"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir + "/out.glb"));
  RunResult bvh = RunProgram(env, testing::MocapfillExe(),
                             "convert " + Quote(FixtureBvhFiles().at(0)) + " " + Quote(dir + "/bvh.glb"));
  EXPECT_EQ(bvh.exit_code, 0) << bvh.output;
}

// Installed layout: <prefix>/bin/mocapfill hands an FBX to <prefix>/libexec/mocapfill/
// mocapfill-full, which finds <prefix>/lib/mocapfill/mocapfill_assimp.so; a BVH conversion
// maps neither the plug-in nor libassimp (the dynamic linker's own report of every file it
// loads says so; the front end, static outside sanitizer builds, loads nothing at all).
TEST(Cli, PluginIsFoundInTheInstalledLayoutAndOnlyLoadedForAssimpFormats) {
  const std::string prefix = testing::ScratchDir("cli_installed");
  fs::create_directories(prefix + "/bin");
  fs::create_directories(prefix + "/lib/mocapfill");
  fs::create_directories(prefix + "/libexec/mocapfill");
  const fs::path built = testing::MocapfillExe();
  fs::copy_file(built, prefix + "/bin/mocapfill");
  fs::copy_file(built.parent_path() / "mocapfill-full", prefix + "/libexec/mocapfill/mocapfill-full");
  fs::copy_file(built.parent_path() / "mocapfill_assimp.so", prefix + "/lib/mocapfill/mocapfill_assimp.so");
  const std::string exe = Quote(prefix + "/bin/mocapfill");
  RunResult fbx = RunProgram("LD_DEBUG=files", exe,
                             "convert " + Quote(testing::FixturePath("fbx/pivot_chain.fbx")) + " " +
                                 Quote(prefix + "/fbx.glb"));
  ASSERT_EQ(fbx.exit_code, 0) << fbx.output;
  EXPECT_NE(fbx.output.find("file=" + prefix + "/lib/mocapfill/mocapfill_assimp.so"), std::string::npos)
      << fbx.output;
  RunResult bvh = RunProgram("LD_DEBUG=files", exe,
                             "convert " + Quote(FixtureBvhFiles().at(0)) + " " + Quote(prefix + "/bvh.glb"));
  ASSERT_EQ(bvh.exit_code, 0) << bvh.output;
  EXPECT_EQ(bvh.output.find("mocapfill_assimp"), std::string::npos) << bvh.output;
  EXPECT_EQ(bvh.output.find("libassimp"), std::string::npos) << bvh.output;
  EXPECT_EQ(bvh.output.find("mocapfill-full"), std::string::npos) << bvh.output;
}

// A successful conversion over an existing output swaps the new file in (file_io.cc) and
// leaves nothing else behind; a symbolic link at the output is replaced, not followed, and
// a folder there is an output failure that leaves the folder alone.
TEST(Cli, ReplacingAnOutputLeavesExactlyTheNewFile) {
  const std::string dir = testing::ScratchDir("cli_replace");
  const std::string in = FixtureBvhFiles().at(0);
  const std::string out = dir + "/out.glb";
  { std::ofstream(out) << "previous content"; }
  ASSERT_EQ(RunCli("convert " + Quote(in) + " " + Quote(out)).exit_code, 0);
  ASSERT_EQ(RunCli("convert " + Quote(in) + " " + Quote(dir + "/fresh.glb")).exit_code, 0);
  EXPECT_EQ(ReadAll(out), ReadAll(dir + "/fresh.glb"));
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"fresh.glb", "out.glb"}));

  const std::string target = dir + "/target.txt", link = dir + "/link.glb";
  { std::ofstream(target) << "link target"; }
  fs::create_symlink(target, link);
  ASSERT_EQ(RunCli("convert " + Quote(in) + " " + Quote(link)).exit_code, 0);
  EXPECT_FALSE(fs::is_symlink(link));
  EXPECT_EQ(ReadAll(link), ReadAll(dir + "/fresh.glb"));
  EXPECT_EQ(ReadAll(target), "link target");

  const std::string folder = dir + "/folder.glb";
  fs::create_directories(folder + "/inside");
  RunResult r = RunCli("convert " + Quote(in) + " " + Quote(folder));
  EXPECT_EQ(r.exit_code, 4) << r.output;
  EXPECT_NE(r.output.find("folder.glb"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_directory(folder + "/inside"));
}

// mocapfill runs convert and inspect itself and hands everything else to mocapfill-full,
// found beside it (build tree) or in <prefix>/libexec/mocapfill (installed). A conversion
// never maps the solver's libraries; without mocapfill-full the format verbs still work and
// the others fail with exit 3 naming what is missing.
TEST(Cli, FormatVerbsRunInTheFrontEndAndTheRestInMocapfillFull) {
  const std::string prefix = testing::ScratchDir("cli_front_end");
  fs::create_directories(prefix + "/bin");
  fs::create_directories(prefix + "/libexec/mocapfill");
  const fs::path built = testing::MocapfillExe();
  fs::copy_file(built, prefix + "/bin/mocapfill");
  const std::string exe = Quote(prefix + "/bin/mocapfill");
  const std::string bvh = Quote(FixtureBvhFiles().at(0));

  RunResult alone = RunProgram("", exe, "fill --help");
  EXPECT_EQ(alone.exit_code, 3) << alone.output;
  EXPECT_NE(alone.output.find(prefix + "/libexec/mocapfill/mocapfill-full"), std::string::npos) << alone.output;
  RunResult convert = RunProgram("LD_DEBUG=files", exe, "convert " + bvh + " " + Quote(prefix + "/a.glb"));
  ASSERT_EQ(convert.exit_code, 0) << convert.output;
  for (const char* solver_library : {"libmetis", "libunwind", "libceres", "libglog"})
    EXPECT_EQ(convert.output.find(solver_library), std::string::npos) << solver_library << ":\n" << convert.output;
  EXPECT_EQ(RunProgram("", exe, "-q inspect " + bvh).exit_code, 0);
  // Assimp inputs need mocapfill-full too.
  RunResult fbx_alone = RunProgram("", exe, "inspect " + Quote(testing::FixturePath("fbx/pivot_chain.fbx")));
  EXPECT_EQ(fbx_alone.exit_code, 3) << fbx_alone.output;
  EXPECT_NE(fbx_alone.output.find("mocapfill-full"), std::string::npos) << fbx_alone.output;

  fs::copy_file(built.parent_path() / "mocapfill-full", prefix + "/libexec/mocapfill/mocapfill-full");
  RunResult version = RunProgram("", exe, "--version");
  EXPECT_EQ(version.exit_code, 0) << version.output;
  EXPECT_NE(version.output.find("mocapfill "), std::string::npos) << version.output;
  RunResult help = RunProgram("", exe, "fill --help");
  EXPECT_EQ(help.exit_code, 0) << help.output;
  EXPECT_NE(help.output.find("Usage: " + prefix + "/bin/mocapfill fill"), std::string::npos) << help.output;
  RunResult unknown = RunProgram("", exe, "no-such-verb");
  EXPECT_EQ(unknown.exit_code, 1) << unknown.output;
  // The installed default database is the one beside <prefix>/share: a broken one there is
  // reported by its installed path.
  fs::create_directories(prefix + "/share/mocapfill/default_db");
  { std::ofstream(prefix + "/share/mocapfill/default_db/broken.bvh") << "HIERARCHY\nROOT"; }
  RunResult fill = RunProgram("", exe, "fill " + Quote(testing::FixturePath("sketches/walk_proud_002_legs8.glb")) +
                                           " -o " + Quote(prefix + "/filled.glb"));
  EXPECT_EQ(fill.exit_code, 2) << fill.output;
  EXPECT_NE(fill.output.find(prefix + "/share/mocapfill/default_db/broken.bvh"), std::string::npos) << fill.output;
  EXPECT_FALSE(fs::exists(prefix + "/filled.glb"));
}

}  // namespace
}  // namespace mocapfill
