// Assimp reads in a child process (formats/assimp/isolated_read.h): the scene that comes
// back through the pipe is the one read in process, bit for bit; a reader that crashes,
// hangs, runs out of memory or answers garbage becomes an error naming the file.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "formats/assimp/assimp_loader.h"
#include "formats/assimp/assimp_reader.h"
#include "formats/assimp/isolated_read.h"
#include "formats/assimp/scene_wire.h"
#include "formats/motion_io.h"
#include "tests/support/test_paths.h"

#if defined(__SANITIZE_ADDRESS__)
#define MOCAPFILL_TEST_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MOCAPFILL_TEST_UNDER_ASAN 1
#endif
#endif

namespace mocapfill {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> AssimpInputs() {
  std::vector<std::string> files = testing::FixtureFiles("fbx", ".fbx");
  if (!testing::DataDir().empty()) {
    files.push_back(testing::DataPath("geno/Geno.fbx"));
    for (const std::string& f : testing::CorpusFiles("assimp", ".fbx")) files.push_back(f);
  }
  return files;
}

TEST(IsolatedRead, TheSceneComesBackBitForBit) {
  const std::vector<std::string> files = AssimpInputs();
  ASSERT_GE(files.size(), 2u);
  for (const std::string& f : files) {
    SCOPED_TRACE(f);
    const Result<Scene> isolated = ImportFile(f);
    const Result<Scene> in_process = ReadWithAssimp(f, ImportOptions{});
    ASSERT_TRUE(in_process.ok()) << in_process.status().message();
    ASSERT_TRUE(isolated.ok()) << isolated.status().message();
    const std::string bytes = EncodeSceneResult(in_process);
    EXPECT_EQ(EncodeSceneResult(isolated), bytes);
    EXPECT_GT(isolated->skeleton.num_joints(), 0);
  }
}

TEST(IsolatedRead, CutBytesAreRefusedNotTrusted) {
  const Result<Scene> scene = ReadWithAssimp(testing::FixturePath("fbx/pivot_chain.fbx"), ImportOptions{});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const std::string bytes = EncodeSceneResult(scene);
  ASSERT_TRUE(DecodeSceneResult(bytes, "x.fbx").ok());
  for (size_t cut = 0; cut < bytes.size(); cut += 1 + cut / 16) {
    const Result<Scene> back = DecodeSceneResult(std::string_view(bytes).substr(0, cut), "x.fbx");
    ASSERT_FALSE(back.ok()) << cut;
    EXPECT_EQ(back.status().code(), ErrorCode::kInvalidData);
    EXPECT_NE(back.status().message().find("x.fbx"), std::string::npos);
  }
  EXPECT_FALSE(DecodeSceneResult(bytes + "x", "x.fbx").ok());
  // An error travels with its code and message.
  const Result<Scene> error = DecodeSceneResult(EncodeSceneResult(Unsupported("no")), "x.fbx");
  EXPECT_EQ(error.status().code(), ErrorCode::kUnsupported);
  EXPECT_EQ(error.status().message(), "no");
}

Result<Scene> Fine() {
  Scene s;
  s.source.format = "test";
  return s;
}

TEST(IsolatedRead, CrashHangAndGarbageBecomeErrorsNamingTheFile) {
  IsolationLimits limits;
  limits.timeout_s = 0.5;
  const Result<Scene> crash = ReadIsolated("crash.fbx", limits, []() -> Result<Scene> {
    raise(SIGSEGV);
    return Fine();
  });
  ASSERT_FALSE(crash.ok());
  EXPECT_EQ(crash.status().code(), ErrorCode::kInvalidData);
  EXPECT_NE(crash.status().message().find("crash.fbx: the Assimp reader crashed on this file (signal 11"),
            std::string::npos)
      << crash.status().message();

  const Result<Scene> hang = ReadIsolated("hang.fbx", limits, []() -> Result<Scene> {
    sleep(60);
    return Fine();
  });
  ASSERT_FALSE(hang.ok());
  EXPECT_NE(hang.status().message().find("hang.fbx: the Assimp reader took longer than 0.5 s"), std::string::npos)
      << hang.status().message();

  const Result<Scene> quits = ReadIsolated("quit.fbx", limits, []() -> Result<Scene> { _exit(5); });
  EXPECT_NE(quits.status().message().find("quit.fbx: the Assimp reader ended with exit code 5"), std::string::npos)
      << quits.status().message();

  const Result<Scene> fine = ReadIsolated("fine.fbx", limits, Fine);
  ASSERT_TRUE(fine.ok()) << fine.status().message();
  EXPECT_EQ(fine->source.format, "test");
}

TEST(IsolatedRead, OutOfMemoryIsAnError) {
#ifdef MOCAPFILL_TEST_UNDER_ASAN
  GTEST_SKIP() << "no address-space limit under AddressSanitizer (its shadow needs terabytes)";
#else
  IsolationLimits limits;
  limits.memory_mb = 256;
  const Result<Scene> greedy = ReadIsolated("greedy.fbx", limits, []() -> Result<Scene> {
    std::vector<std::vector<char>> hog;
    for (int i = 0; i < 64; ++i) hog.emplace_back(size_t{64} << 20, 'x');  // 4 GiB
    return Fine();
  });
  ASSERT_FALSE(greedy.ok());
  EXPECT_NE(greedy.status().message().find("greedy.fbx: the Assimp reader ran out of memory on this file (limit 256 MiB"),
            std::string::npos)
      << greedy.status().message();
#endif
}

// Assimp's own BVH loader recurses once per level: 200,000 nested joints overflow its stack.
TEST(IsolatedRead, DeepHierarchyCrashingAssimpIsAnError) {
  const fs::path path = fs::path(testing::ScratchDir("IsolatedRead.DeepHierarchy")) / "deep_200000.bvh";
  {
    std::ofstream out(path);
    constexpr int kDepth = 200'000;
    out << "HIERARCHY\nROOT j0\n{\nOFFSET 0 0 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
    for (int i = 1; i < kDepth; ++i) out << "JOINT j" << i << "\n{\nOFFSET 0 1 0\nCHANNELS 3 Zrotation Xrotation Yrotation\n";
    out << "End Site\n{\nOFFSET 0 1 0\n}\n";
    for (int i = 0; i < kDepth; ++i) out << "}\n";
    out << "MOTION\nFrames: 1\nFrame Time: 0.033333\n";
    for (int i = 0; i < kDepth; ++i) out << "0 0 0 ";
    out << "\n";
  }
  const Result<Scene> scene = ReadWithAssimpModule(path.string(), ImportOptions{});
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.status().code(), ErrorCode::kInvalidData);
  EXPECT_NE(scene.status().message().find(path.string() + ": the Assimp reader crashed on this file (signal 11"),
            std::string::npos)
      << scene.status().message();
  RecordProperty("deep_bvh_outcome", scene.status().message());
}

}  // namespace
}  // namespace mocapfill
