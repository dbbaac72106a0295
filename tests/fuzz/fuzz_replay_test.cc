// Replays every kept fuzz input through its target in the ordinary test run: the inputs in
// tests/fuzz/regressions/<target>/ are inputs that can make a reader crash, leak, hang or
// exhaust memory (each file's name says what it found), and must be refused or read cleanly. The
// shipped fixtures of each target's format run through it too, so every target is known to
// accept what it is seeded with (tools/fuzz.sh seeds from the same files).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "formats/motion_io.h"
#include "tests/fuzz/fuzz_targets.h"
#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace mocapfill::fuzz {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> FilesUnder(const fs::path& folder) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : fs::recursive_directory_iterator(folder, ec))
    if (entry.is_regular_file()) files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

int Replay(const FuzzTarget& target, const std::vector<std::string>& files) {
  int count = 0;
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    const std::string bytes = testing::ReadAll(file);
    EXPECT_EQ(target.run(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size()), 0);
    ++count;
  }
  return count;
}

const FuzzTarget& Target(const std::string& name) {
  for (const FuzzTarget& target : AllFuzzTargets())
    if (name == target.name) return target;
  throw std::runtime_error("no fuzz target " + name);
}

TEST(FuzzRegressions, EveryKeptInputIsHandledCleanly) {
  int total = 0;
  for (const FuzzTarget& target : AllFuzzTargets())
    total += Replay(target, FilesUnder(fs::path(MOCAPFILL_FUZZ_REGRESSIONS_DIR) / target.name));
  RecordProperty("inputs", total);
}

// Files on which Assimp itself aborts: read in its child process, each is an error naming the
// file (the fbx target cannot tell, since the child's crash never reaches libFuzzer).
TEST(FuzzRegressions, AssimpCrashesEndAsErrorsNamingTheFile) {
  const std::vector<std::string> inputs = FilesUnder(fs::path(MOCAPFILL_FUZZ_REGRESSIONS_DIR) / "fbx");
  ASSERT_GE(inputs.size(), 3u);
  const std::string dir = testing::ScratchDir("FuzzRegressions.AssimpCrashes");
  for (const std::string& input : inputs) {
    const std::string path = dir + "/" + fs::path(input).filename().string() + ".fbx";
    fs::copy_file(input, path, fs::copy_options::overwrite_existing);
    const Result<Scene> scene = ImportFile(path);
    ASSERT_FALSE(scene.ok()) << path;
    EXPECT_EQ(scene.status().code(), ErrorCode::kInvalidData);
    EXPECT_EQ(scene.status().message().rfind(path + ": the Assimp reader crashed on this file (signal", 0), 0u)
        << scene.status().message();
    EXPECT_EQ(scene.status().message().find("memory"), std::string::npos) << scene.status().message();
  }
}

// Each target on the fixtures of its format, good and bad ones alike.
TEST(FuzzSeeds, BvhFixtures) { EXPECT_GE(Replay(Target("bvh"), testing::FixtureFiles("", ".bvh")), 40); }

TEST(FuzzSeeds, GltfFixtures) {
  const int gltf = Replay(Target("gltf"), testing::FixtureFiles("", ".gltf"));
  EXPECT_GE(gltf + Replay(Target("gltf"), testing::FixtureFiles("", ".glb")), 10);
}

TEST(FuzzSeeds, FbxFixtures) { EXPECT_GE(Replay(Target("fbx"), testing::FixtureFiles("fbx", ".fbx")), 2); }

TEST(FuzzSeeds, PipelineFixtures) {
  EXPECT_GE(Replay(Target("pipeline"), testing::FixtureFiles("pipelines", ".json")), 6);
}

}  // namespace
}  // namespace mocapfill::fuzz
