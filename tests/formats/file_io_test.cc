// Whole-file reads (regular files, pipes, failures) and atomic writes.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "formats/atomic_writer.h"
#include "formats/file_io.h"
#include "tests/formats/file_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::FeedFifo;
using testing::Pattern;

TEST(ReadFileBytes, ReadsRegularFilesWhole) {
  const std::string dir = testing::ScratchDir("read_file_bytes");
  for (size_t bytes : {size_t{0}, size_t{17}, (size_t{2} << 20) + 5}) {
    const std::string path = dir + "/f" + std::to_string(bytes);
    const std::string pattern = Pattern(bytes);
    ASSERT_TRUE(WriteFileAtomic(path, pattern).ok());
    const Result<std::string> read = ReadFileBytes(path);
    ASSERT_TRUE(read.ok()) << read.status().message();
    EXPECT_EQ(*read, pattern) << bytes;
  }
}

TEST(ReadFileBytes, ReadsPipesToTheirEnd) {
  const std::string dir = testing::ScratchDir("read_file_bytes_pipe");
  const std::string fifo = dir + "/pipe";
  const std::string pattern = Pattern(700000);
  std::thread writer = FeedFifo(fifo, pattern);
  const Result<std::string> read = ReadFileBytes(fifo);
  writer.join();
  ASSERT_TRUE(read.ok()) << read.status().message();
  EXPECT_EQ(*read, pattern);
}

TEST(ReadFileBytes, FailuresNameThePath) {
  const std::string dir = testing::ScratchDir("read_file_bytes_fail");
  const Result<std::string> missing = ReadFileBytes(dir + "/missing.bvh");
  EXPECT_EQ(missing.status().code(), ErrorCode::kIoError);
  EXPECT_NE(missing.status().message().find(dir + "/missing.bvh: cannot open"), std::string::npos);
  const Result<std::string> folder = ReadFileBytes(dir);
  EXPECT_EQ(folder.status().code(), ErrorCode::kIoError);
  EXPECT_NE(folder.status().message().find("is a directory"), std::string::npos);
}

std::vector<std::string> FolderEntries(const std::string& dir) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

ino_t InodeOf(const std::string& path) {
  struct stat info {};
  EXPECT_EQ(::stat(path.c_str(), &info), 0) << path;
  return info.st_ino;
}

// A run of outputs over existing files: each replaced file is overwritten for the next
// output (its inode moves on to the next path), contents are exact whatever the sizes,
// and once the writer is gone only the outputs are left.
TEST(AtomicWriter, ReplacedFilesAreReusedForTheNextOutputAndRemovedAtTheEnd) {
  const std::string dir = testing::ScratchDir("atomic_writer_reuse");
  const std::vector<std::string> names = {"a.glb", "b.glb", "c.glb", "d.glb"};
  for (const std::string& name : names) ASSERT_TRUE(WriteFileAtomic(dir + "/" + name, Pattern(50000)).ok());
  const std::vector<size_t> sizes = {200000, 10, 70000, 0};
  {
    AtomicWriter writer;
    ino_t replaced = 0;
    for (size_t i = 0; i < names.size(); ++i) {
      const std::string path = dir + "/" + names[i];
      const ino_t before = InodeOf(path);
      const std::string content = Pattern(sizes[i]) + names[i];
      ASSERT_TRUE(writer.Write(path, {content.substr(0, 3), content.substr(3)}).ok());
      EXPECT_EQ(ReadFileBytes(path).value(), content);
      if (i > 0) {
        EXPECT_EQ(InodeOf(path), replaced) << "the file replaced by the write before";
      }
      replaced = before;
      EXPECT_EQ(FolderEntries(dir).size(), names.size() + 1) << "the outputs and one spare";
    }
  }
  EXPECT_EQ(FolderEntries(dir), names);
}

// A process that has exited: its pid names no process (until the kernel hands it out again,
// which takes a full turn of the pid space).
pid_t ExitedProcessId() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

// What a batch killed with SIGKILL leaves (NAME.tmp-PID of a process gone) is removed; the
// temporaries of running processes, and files that only look similar, are not.
TEST(AtomicWriter, StaleTemporariesOfExitedProcessesAreRemoved) {
  const std::string dir = testing::ScratchDir("atomic_writer_stale");
  const std::string gone = std::to_string(ExitedProcessId());
  const std::vector<std::string> kept = {"a.glb", "b.glb.tmp-" + std::to_string(::getpid()),
                                         "c.glb.tmp-" + std::to_string(::getppid()), "d.glb.tmp-x1", ".tmp-" + gone,
                                         "e.glb.tmp-"};
  for (const std::string& name : kept) ASSERT_TRUE(WriteFileAtomic(dir + "/" + name, "x").ok());
  for (const std::string& name : {"f.glb.tmp-" + gone, "g.bvh.tmp-" + gone})
    ASSERT_TRUE(WriteFileAtomic(dir + "/" + name, "partial").ok());
  EXPECT_EQ(RemoveStaleTemporaries(dir), 2u);
  std::vector<std::string> expected = kept;
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(FolderEntries(dir), expected);
  EXPECT_EQ(RemoveStaleTemporaries(dir + "/missing"), 0u);
}

// A replaced file that another name still links to is never written over, and a reused
// file gets the mode a new file gets rather than the one it had.
TEST(AtomicWriter, LinkedSparesAreLeftAloneAndReusedOnesTakeANewFilesMode) {
  const std::string dir = testing::ScratchDir("atomic_writer_links");
  for (const char* name : {"/a.glb", "/b.glb", "/c.glb"}) ASSERT_TRUE(WriteFileAtomic(dir + name, "old").ok());
  ASSERT_EQ(::link((dir + "/a.glb").c_str(), (dir + "/a_link.glb").c_str()), 0);
  {
    AtomicWriter writer;
    ASSERT_TRUE(writer.Write(dir + "/a.glb", {"new a"}).ok());  // fresh file; the old a is the spare, linked twice
    const ino_t linked = InodeOf(dir + "/a_link.glb");
    ASSERT_TRUE(writer.Write(dir + "/b.glb", {"new b"}).ok());
    EXPECT_NE(InodeOf(dir + "/b.glb"), linked);
    EXPECT_EQ(ReadFileBytes(dir + "/a_link.glb").value(), "old");
    const mode_t fresh = static_cast<mode_t>(std::filesystem::status(dir + "/b.glb").permissions());
    // The old b is the spare now; while someone reads it, it is not written over.
    std::string spare;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().string().find(".tmp-") != std::string::npos) spare = entry.path().string();
    ASSERT_FALSE(spare.empty());
    {
      const int reader = ::open(spare.c_str(), O_RDONLY);
      ASSERT_GE(reader, 0);
      const ino_t read_inode = InodeOf(spare);
      ASSERT_TRUE(writer.Write(dir + "/c.glb", {"newer c"}).ok());
      EXPECT_NE(InodeOf(dir + "/c.glb"), read_inode);
      char held[8] = {};
      EXPECT_EQ(::pread(reader, held, sizeof(held), 0), 3);
      EXPECT_EQ(std::string(held), "old");
      ::close(reader);
    }
    // The first c is the spare now: made 0600, it is still reused, with the fresh mode.
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().string().find(".tmp-") != std::string::npos) ::chmod(entry.path().c_str(), 0600);
    ASSERT_TRUE(writer.Write(dir + "/c.glb", {"new c"}).ok());
    EXPECT_EQ(static_cast<mode_t>(std::filesystem::status(dir + "/c.glb").permissions()), fresh);
    EXPECT_EQ(ReadFileBytes(dir + "/c.glb").value(), "new c");
    // Another folder: a new file there, the spare stays where it was.
    const std::string other = testing::ScratchDir("atomic_writer_links_other");
    ASSERT_TRUE(writer.Write(other + "/d.glb", {"new d"}).ok());
    EXPECT_EQ(ReadFileBytes(other + "/d.glb").value(), "new d");
  }
  EXPECT_EQ(FolderEntries(dir), (std::vector<std::string>{"a.glb", "a_link.glb", "b.glb", "c.glb"}));
}

// Interrupted (SIGTERM) while holding a spare: the spare is removed, the process still
// ends by the signal.
TEST(AtomicWriter, InterruptedWritersLeaveNoSpareBehind) {
  const std::string dir = testing::ScratchDir("atomic_writer_signal");
  ASSERT_TRUE(WriteFileAtomic(dir + "/a.glb", "old").ok());
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    AtomicWriter writer;
    if (!writer.Write(dir + "/a.glb", {"new"}).ok()) ::_exit(3);
    if (FolderEntries(dir).size() != 2) ::_exit(4);  // the output and its spare
    ::raise(SIGTERM);
    ::_exit(5);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << "exit " << WEXITSTATUS(status);
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_EQ(FolderEntries(dir), std::vector<std::string>{"a.glb"});
  EXPECT_EQ(ReadFileBytes(dir + "/a.glb").value(), "new");
}

}  // namespace
}  // namespace mocapfill
