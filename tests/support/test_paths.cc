#include "tests/support/test_paths.h"

#include <algorithm>
#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace mocapfill::testing {

std::string FixturePath(const std::string& relative) { return std::string(MOCAPFILL_FIXTURES_DIR) + "/" + relative; }

std::string DataDir() {
  std::error_code ec;
  // MOCAPFILL_DATA_DIR in the environment points the tests at a corpus elsewhere (or, set to a
  // missing folder, runs them as a fresh clone would: what skips then is labelled `corpus`).
  const char* from_env = std::getenv("MOCAPFILL_DATA_DIR");
  const fs::path dir(from_env && *from_env ? from_env : MOCAPFILL_DATA_DIR);
  if (fs::is_directory(dir, ec)) return fs::canonical(dir, ec).string();
  return "";
}

std::string DataPath(const std::string& relative) { return DataDir() + "/" + relative; }

namespace {

std::vector<std::string> FilesWithExtension(const std::string& folder, const std::string& ext) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : fs::recursive_directory_iterator(folder, ec))
    if (entry.is_regular_file() && entry.path().extension() == ext) files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

std::vector<std::string> FixtureFiles(const std::string& folder, const std::string& ext) {
  return FilesWithExtension(FixturePath(folder), ext);
}

std::vector<std::string> CorpusFiles(const std::string& folder, const std::string& ext) {
  const std::string root = DataDir();
  if (root.empty()) return {};
  return FilesWithExtension(root + "/" + folder, ext);
}

std::string ScratchDir(const std::string& test_name) {
  // ctest runs tests in parallel processes: tests sharing a scratch name (a fixture's SetUp)
  // must not clear each other's files, so the running test's own name is appended.
  fs::path dir = fs::path(MOCAPFILL_BINARY_DIR) / "test-scratch" / test_name;
  if (const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info()) {
    std::string unique = std::string(info->test_suite_name()) + "." + info->name();
    for (char& c : unique)
      if (c == '/') c = '_';
    dir /= unique;
  }
  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir, ec);
  return dir.string();
}

std::string TestOutputDir(const std::string& sub) {
  const fs::path dir = fs::path(MOCAPFILL_BINARY_DIR) / "test-output" / sub;
  std::error_code ec;
  fs::create_directories(dir, ec);
  return dir.string();
}

std::string MocapfillExe() { return std::string(MOCAPFILL_BINARY_DIR) + "/converter/mocapfill"; }

}  // namespace mocapfill::testing
