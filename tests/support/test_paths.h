// Where tests find their data: shipped fixtures (always present) and the shared corpus
// (../shared/data, present in CI; tests over it skip with a visible message elsewhere).
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace mocapfill::testing {

// Absolute path of a file under fixtures/, e.g. FixturePath("bvh/cmu_01_01_short.bvh").
std::string FixturePath(const std::string& relative);

// Every file under fixtures/<folder> (recursively) whose extension is `ext` (".bvh"), sorted.
std::vector<std::string> FixtureFiles(const std::string& folder, const std::string& ext);

// The shared corpus folder, or "" when it is absent.
std::string DataDir();

// Absolute path of a file under the shared corpus (may not exist).
std::string DataPath(const std::string& relative);

// Every file under `folder` of the corpus whose extension is `ext` (".bvh"), sorted.
std::vector<std::string> CorpusFiles(const std::string& folder, const std::string& ext);

// A fresh, empty scratch directory for one test (under the build tree).
std::string ScratchDir(const std::string& test_name);

// <build>/test-output/<sub>, created if needed. Every glTF a test writes goes under
// <build>/test-output so that CI validates all of them with the Khronos glTF-Validator.
std::string TestOutputDir(const std::string& sub);

// The path of the built mocapfill executable.
std::string MocapfillExe();

}  // namespace mocapfill::testing

// Skips the current test with a visible message when the shared corpus is missing.
#define MOCAPFILL_REQUIRE_CORPUS()                                                        \
  do {                                                                                    \
    if (::mocapfill::testing::DataDir().empty())                                          \
      GTEST_SKIP() << "shared corpus not found (../shared/data): corpus test skipped";    \
  } while (0)
