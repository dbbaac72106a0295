// Replays every kept fuzz input through its target in the ordinary test run: the inputs in
// tests/fuzz/regressions/<target>/ once made a reader crash, leak, hang or exhaust memory
// (each file's name says what it found), and must now be refused or read cleanly. The
// shipped fixtures of each target's format run through it too, so every target is known to
// accept what it is seeded with (tools/fuzz.sh seeds from the same files).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "tests/fuzz/fuzz_targets.h"
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

std::string Bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

int Replay(const FuzzTarget& target, const std::vector<std::string>& files) {
  int count = 0;
  for (const std::string& file : files) {
    SCOPED_TRACE(file);
    const std::string bytes = Bytes(file);
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

// Each target on the fixtures of its format, good and bad ones alike.
TEST(FuzzSeeds, BvhFixtures) {
  std::vector<std::string> files;
  for (const std::string& file : FilesUnder(testing::FixturePath("")))
    if (fs::path(file).extension() == ".bvh") files.push_back(file);
  EXPECT_GE(Replay(Target("bvh"), files), 40);
}

TEST(FuzzSeeds, GltfFixtures) {
  std::vector<std::string> files;
  for (const std::string& file : FilesUnder(testing::FixturePath("")))
    if (fs::path(file).extension() == ".gltf" || fs::path(file).extension() == ".glb") files.push_back(file);
  EXPECT_GE(Replay(Target("gltf"), files), 10);
}

TEST(FuzzSeeds, PipelineFixtures) {
  EXPECT_GE(Replay(Target("pipeline"), FilesUnder(testing::FixturePath("pipelines"))), 6);
}

}  // namespace
}  // namespace mocapfill::fuzz
