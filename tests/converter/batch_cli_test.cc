// What a batch leaves behind when it is killed, and what two processes writing the same
// output leave: never a partial or mixed file under a final name.
#include <gtest/gtest.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

namespace fs = std::filesystem;
using testing::StartCli;

int Wait(pid_t pid) { return testing::WaitCli(pid).exit_code; }

// A complete .glb: the header's total length is the file's size and the JSON chunk fits.
bool IsCompleteGlb(const std::string& bytes) {
  if (bytes.size() < 20 || bytes.compare(0, 4, "glTF") != 0) return false;
  uint32_t length = 0, json_length = 0;
  std::memcpy(&length, bytes.data() + 8, 4);
  std::memcpy(&json_length, bytes.data() + 12, 4);
  return length == bytes.size() && 20 + uint64_t{json_length} <= bytes.size();
}

// Killed with SIGKILL at several moments of a batch: every file under a final name is whole;
// the next batch into the folder finishes every output and removes the killed run's
// temporary files.
TEST(BatchCli, KilledBatchLeavesOnlyWholeOutputsAndTheNextRunCleansUp) {
  const std::string dir = testing::ScratchDir("batch_killed");
  std::vector<std::string> args = {"convert"};
  const std::vector<std::string> clips = testing::FixtureFiles("default_db", ".bvh");
  ASSERT_GE(clips.size(), 10u);
  args.insert(args.end(), clips.begin(), clips.end());
  for (const char* extra : {"-o", dir.c_str(), "--format", "glb", "-j", "2"}) args.push_back(extra);
  for (int delay_ms : {5, 20, 40, 80}) {
    const pid_t pid = StartCli(args);
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    ::kill(pid, SIGKILL);
    Wait(pid);
    for (const auto& entry : fs::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (name.find(".tmp-") != std::string::npos) continue;  // a temporary: allowed, cleaned below
      EXPECT_TRUE(IsCompleteGlb(testing::ReadAll(entry.path().string())))
          << name << " after a kill at " << delay_ms << " ms";
    }
  }
  // A temporary as a kill leaves it, in case none of the kills above came mid-write.
  const pid_t exited = StartCli({"--version"});
  Wait(exited);
  { std::ofstream(dir + "/dataset-1_run_happy_001.glb.tmp-" + std::to_string(exited)) << "glTF partial"; }
  ASSERT_EQ(Wait(StartCli(args)), 0);
  size_t outputs = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(name.find(".tmp-"), std::string::npos) << name << " left behind";
    EXPECT_TRUE(IsCompleteGlb(testing::ReadAll(entry.path().string()))) << name;
    ++outputs;
  }
  EXPECT_EQ(outputs, clips.size());
}

// Two processes converting different clips to one output name at the same moment: the file
// is always exactly one of the two conversions, never a mix, and no temporary is left.
TEST(BatchCli, TwoWritersOfOneOutputLeaveOneWholeFile) {
  const std::string dir = testing::ScratchDir("batch_two_writers");
  const std::vector<std::string> clips = testing::FixtureFiles("default_db", ".bvh");
  const std::string a = clips.at(0), b = clips.at(1);
  ASSERT_EQ(Wait(StartCli({"convert", a, dir + "/a.glb"})), 0);
  ASSERT_EQ(Wait(StartCli({"convert", b, dir + "/b.glb"})), 0);
  const std::string bytes_a = testing::ReadAll(dir + "/a.glb"), bytes_b = testing::ReadAll(dir + "/b.glb");
  ASSERT_NE(bytes_a, bytes_b);
  const std::string out = dir + "/out.glb";
  int saw_a = 0, saw_b = 0;
  for (int round = 0; round < 20; ++round) {
    const pid_t first = StartCli({"convert", a, out});
    const pid_t second = StartCli({"convert", b, out});
    EXPECT_EQ(Wait(first), 0);
    EXPECT_EQ(Wait(second), 0);
    const std::string got = testing::ReadAll(out);
    ASSERT_TRUE(got == bytes_a || got == bytes_b) << "round " << round << ": " << got.size() << " bytes, a mix";
    (got == bytes_a ? saw_a : saw_b)++;
  }
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos) << entry.path();
  RecordProperty("first_won", saw_a);
  RecordProperty("second_won", saw_b);
}

}  // namespace
}  // namespace mocapfill
