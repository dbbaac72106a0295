// The fast path's memory and input text: LargeBuffer, heap reservation, whole-file reads into
// a LargeBuffer and mapped inputs (ReadFileText), truncation under a mapping included.
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
#include "formats/fast_convert/file_text.h"
#include "formats/fast_convert/large_buffer.h"
#include "tests/formats/file_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::FeedFifo;
using testing::Pattern;

TEST(LargeBuffer, HoldsWhatIsWrittenBelowAndAboveItsOwnMappingSize) {
  for (size_t bytes : {size_t{0}, size_t{1}, size_t{4096}, (size_t{1} << 20) - 1, size_t{1} << 20,
                       (size_t{5} << 20) + 123}) {
    LargeBuffer buffer(bytes);
    ASSERT_EQ(buffer.size(), bytes);
    ASSERT_NE(buffer.data(), nullptr);
    const std::string pattern = Pattern(bytes);
    std::memcpy(buffer.data(), pattern.data(), bytes);
    EXPECT_EQ(buffer.view(), pattern) << bytes;
  }
}

// Minor page faults this process has taken so far.
long MinorFaults() {
  struct rusage usage {};
  ::getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

// A buffer below its own mapping size comes from malloc, which maps a fresh block from
// 128 KiB: its pages are mapped when it is made, not faulted in one by one as it is filled.
TEST(LargeBuffer, IsMappedForWritingWhenMade) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer's allocator";
#endif
  constexpr size_t kBytes = size_t{640} << 10;  // 160 pages
  LargeBuffer buffer(kBytes);
  const long before = MinorFaults();
  std::memset(buffer.data(), 7, kBytes);
  EXPECT_LT(MinorFaults() - before, 8) << "pages faulted in while filling a 640 KiB buffer";
}

// After ReserveMappedHeap, small allocations that take the heap's top are already mapped:
// filling 600 KB of 8 KB blocks takes (almost) no page faults, where a heap grown on
// demand takes one per 4 KiB page (150 here).
TEST(ReserveMappedHeap, SmallAllocationsFindTheirPagesMapped) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "AddressSanitizer keeps its own heap";
#endif
  ReserveMappedHeap(size_t{1} << 20);
  std::vector<void*> blocks;
  const long before = MinorFaults();
  for (int i = 0; i < 75; ++i) {
    blocks.push_back(std::malloc(8 << 10));
    std::memset(blocks.back(), 1, 8 << 10);
  }
  const long faults = MinorFaults() - before;
  for (void* block : blocks) std::free(block);
  EXPECT_LT(faults, 8) << "page faults while filling 600 KB of new heap blocks";
}

// The kernel's view of the mapping that holds `address` (/proc/self/smaps): its
// "THPeligible" and "Rss" (kB) fields, or -1 each when not found.
struct MappingInfo {
  int thp_eligible = -1;
  long rss_kb = -1;
};
MappingInfo MappingAt(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<uintptr_t>(address);
  std::string line;
  bool inside = false;
  MappingInfo info;
  while (std::getline(smaps, line)) {
    unsigned long begin = 0, end = 0;
    if (std::sscanf(line.c_str(), "%lx-%lx ", &begin, &end) == 2 && line.find(':') > line.find(' ')) {
      if (inside) return info;
      inside = at >= begin && at < end;
    } else if (inside && line.rfind("THPeligible:", 0) == 0) {
      info.thp_eligible = std::atoi(line.c_str() + 12);
    } else if (inside && line.rfind("Rss:", 0) == 0) {
      info.rss_kb = std::atol(line.c_str() + 4);
    }
  }
  return info;
}

bool TransparentHugePagesOff() {
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string text;
  std::getline(mode, text);
  return text.empty() || text.find("[never]") != std::string::npos;
}

// Whole 2 MiB pieces are huge-page eligible; a last piece the buffer fills less than
// 400 KiB of is not (zeroing 2 MiB for it costs more than its small pages), and those
// small pages are already there (faulted in one call).
TEST(LargeBuffer, ShortTailStaysInSmallPagesAlreadyFaultedIn) {
  constexpr size_t kMiB = size_t{1} << 20;
  LargeBuffer short_tail(2 * kMiB + 100000);
  LargeBuffer long_tail(2 * kMiB + 600000);
  const std::string pattern = Pattern(2 * kMiB + 600000);
  std::memcpy(short_tail.data(), pattern.data(), short_tail.size());
  std::memcpy(long_tail.data(), pattern.data(), long_tail.size());
  EXPECT_EQ(short_tail.view(), pattern.substr(0, short_tail.size()));
  EXPECT_EQ(long_tail.view(), pattern);
  if (TransparentHugePagesOff()) GTEST_SKIP() << "transparent huge pages are off here: no eligibility to check";
  EXPECT_EQ(MappingAt(short_tail.data()).thp_eligible, 1);
  EXPECT_EQ(MappingAt(short_tail.data() + 2 * kMiB).thp_eligible, 0);
  EXPECT_EQ(MappingAt(long_tail.data()).thp_eligible, 1);
  EXPECT_EQ(MappingAt(long_tail.data() + 2 * kMiB).thp_eligible, 1);
}

TEST(LargeBuffer, SmallPageTailIsFaultedInUpFront) {
  constexpr size_t kMiB = size_t{1} << 20;
  const LargeBuffer buffer(2 * kMiB + 100000);  // nothing written yet
  const MappingInfo tail = MappingAt(buffer.data() + 2 * kMiB);
  ASSERT_GE(tail.rss_kb, 0) << "no mapping found in /proc/self/smaps";
  EXPECT_GE(tail.rss_kb, 100000 / 1024);
}

TEST(LargeBuffer, GrowingKeepsTheBytesAndMovingHandsThemOver) {
  const std::string pattern = Pattern(300000);
  LargeBuffer buffer(pattern.size());
  std::memcpy(buffer.data(), pattern.data(), pattern.size());
  buffer.resize(3 << 20);  // past 1 MiB: moves to its own mapping
  ASSERT_EQ(buffer.size(), size_t{3} << 20);
  EXPECT_EQ(buffer.view().substr(0, pattern.size()), pattern);
  buffer.resize(10);
  EXPECT_EQ(buffer.view(), pattern.substr(0, 10));
  LargeBuffer moved(std::move(buffer));
  EXPECT_EQ(moved.view(), pattern.substr(0, 10));
  EXPECT_TRUE(buffer.empty());  // NOLINT: moved-from is empty by contract
  LargeBuffer assigned;
  assigned = std::move(moved);
  EXPECT_EQ(assigned.view(), pattern.substr(0, 10));
}

TEST(ReadFileToBuffer, ReadsRegularFilesWhole) {
  const std::string dir = testing::ScratchDir("read_file_to_buffer");
  for (size_t bytes : {size_t{0}, size_t{17}, (size_t{2} << 20) + 5}) {
    const std::string path = dir + "/f" + std::to_string(bytes);
    const std::string pattern = Pattern(bytes);
    ASSERT_TRUE(WriteFileAtomic(path, pattern).ok());
    const Result<LargeBuffer> read = ReadFileToBuffer(path);
    ASSERT_TRUE(read.ok()) << read.status().message();
    EXPECT_EQ(read->view(), pattern) << bytes;
    const Result<std::string> as_string = ReadFileBytes(path);
    ASSERT_TRUE(as_string.ok());
    EXPECT_EQ(*as_string, pattern);
  }
}

// A pipe has no size to go by: it is read in growing chunks to its end.
TEST(ReadFileToBuffer, ReadsPipesToTheirEnd) {
  const std::string dir = testing::ScratchDir("read_file_to_buffer_pipe");
  const std::string fifo = dir + "/pipe";
  const std::string pattern = Pattern(700000);
  std::thread writer = FeedFifo(fifo, pattern);
  const Result<LargeBuffer> read = ReadFileToBuffer(fifo);
  writer.join();
  ASSERT_TRUE(read.ok()) << read.status().message();
  EXPECT_EQ(read->view(), pattern);
}

TEST(ReadFileToBuffer, FailuresNameThePath) {
  const std::string dir = testing::ScratchDir("read_file_to_buffer_fail");
  const Result<LargeBuffer> missing = ReadFileToBuffer(dir + "/missing.bvh");
  EXPECT_EQ(missing.status().code(), ErrorCode::kIoError);
  EXPECT_NE(missing.status().message().find(dir + "/missing.bvh: cannot open"), std::string::npos);
  const Result<LargeBuffer> folder = ReadFileToBuffer(dir);
  EXPECT_EQ(folder.status().code(), ErrorCode::kIoError);
  EXPECT_NE(folder.status().message().find("is a directory"), std::string::npos);
}

TEST(ReadFileText, MapsLargeRegularFilesAndReadsTheRest) {
  const std::string dir = testing::ScratchDir("read_file_text");
  for (size_t bytes : {size_t{0}, size_t{17}, kMapFileMinBytes - 1, kMapFileMinBytes, size_t{3} << 20,
                       (size_t{2} << 20) + 5}) {
    const std::string path = dir + "/f" + std::to_string(bytes);
    const std::string pattern = Pattern(bytes);
    ASSERT_TRUE(WriteFileAtomic(path, pattern).ok());
    Result<FileText> text = ReadFileText(path);
    ASSERT_TRUE(text.ok()) << text.status().message();
    EXPECT_EQ(text->mapped(), bytes >= kMapFileMinBytes) << bytes;
    EXPECT_EQ(text->view(), pattern) << bytes;
    EXPECT_TRUE(text->intact());
    FileText moved = std::move(*text);
    EXPECT_EQ(moved.view(), pattern) << bytes;
  }
  // A pipe is read, whatever the threshold.
  const std::string fifo = dir + "/pipe";
  const std::string pattern = Pattern(300000);
  std::thread writer = FeedFifo(fifo, pattern);
  const Result<FileText> piped = ReadFileText(fifo, 1);
  writer.join();
  ASSERT_TRUE(piped.ok());
  EXPECT_FALSE(piped->mapped());
  EXPECT_EQ(piped->view(), pattern);
  const Result<FileText> missing = ReadFileText(dir + "/missing.bvh");
  EXPECT_EQ(missing.status().code(), ErrorCode::kIoError);
  EXPECT_NE(missing.status().message().find(dir + "/missing.bvh: cannot open"), std::string::npos);
  EXPECT_NE(ReadFileText(dir).status().message().find("is a directory"), std::string::npos);
}

// The threshold an input left to the process's exit is mapped from (file_io.h): the text
// is the file's whatever the size, a page-multiple size included.
TEST(ReadFileText, MapsFromTheThresholdItIsGiven) {
  const std::string dir = testing::ScratchDir("read_file_text_threshold");
  static_assert(kMapLeftInputMinBytes < kMapFileMinBytes);
  for (size_t bytes : {size_t{17}, kMapLeftInputMinBytes - 1, kMapLeftInputMinBytes, size_t{20480}, size_t{300001}}) {
    const std::string path = dir + "/f" + std::to_string(bytes);
    const std::string pattern = Pattern(bytes);
    ASSERT_TRUE(WriteFileAtomic(path, pattern).ok());
    const Result<FileText> text = ReadFileText(path, kMapLeftInputMinBytes);
    ASSERT_TRUE(text.ok()) << text.status().message();
    EXPECT_EQ(text->mapped(), bytes >= kMapLeftInputMinBytes) << bytes;
    EXPECT_EQ(text->view(), pattern) << bytes;
    EXPECT_FALSE(ReadFileText(path)->mapped()) << bytes;  // below kMapFileMinBytes: read
  }
}

// A text left to the process's exit is empty to its owner, and its pages stay mapped
// (read here through the old view, which an munmap would have made fault).
TEST(ReadFileText, TextLeftToExitStaysMapped) {
  const std::string dir = testing::ScratchDir("read_file_text_leave");
  const std::string pattern = Pattern(size_t{2} << 20);
  ASSERT_TRUE(WriteFileAtomic(dir + "/f.bvh", pattern).ok());
  Result<FileText> text = ReadFileText(dir + "/f.bvh");
  ASSERT_TRUE(text.ok() && text->mapped());
  const std::string_view old_view = text->view();
  text->LeaveToExit();
  EXPECT_FALSE(text->mapped());
  EXPECT_TRUE(text->view().empty());
  EXPECT_EQ(old_view, pattern);
}

// A mapped file cut short by someone else: the pages it lost read as zeros instead of
// ending the process with SIGBUS, and the text says it is no longer intact. Another
// mapping's text stays intact.
TEST(ReadFileText, TruncationUnderAMappingIsSurvivedAndReported) {
  const std::string dir = testing::ScratchDir("read_file_text_truncated");
  const std::string path = dir + "/cut.bvh", other_path = dir + "/kept.bvh";
  const std::string pattern = Pattern(size_t{3} << 20);
  ASSERT_TRUE(WriteFileAtomic(path, pattern).ok());
  ASSERT_TRUE(WriteFileAtomic(other_path, pattern).ok());
  const Result<FileText> text = ReadFileText(path);
  const Result<FileText> other = ReadFileText(other_path);
  ASSERT_TRUE(text.ok() && other.ok());
  ASSERT_TRUE(text->mapped());
  const size_t kept = (size_t{1} << 20) + 100;
  ASSERT_EQ(::truncate(path.c_str(), static_cast<off_t>(kept)), 0);
  const std::string_view view = text->view();
  ASSERT_EQ(view.size(), pattern.size());
  EXPECT_EQ(view.substr(0, kept), std::string_view(pattern).substr(0, kept));
  size_t nonzero_after = 0;
  for (size_t i = (kept + 4095) / 4096 * 4096; i < view.size(); ++i) nonzero_after += view[i] != 0;
  EXPECT_EQ(nonzero_after, 0u);
  EXPECT_FALSE(text->intact());
  EXPECT_EQ(other->view(), pattern);
  EXPECT_TRUE(other->intact());
}

}  // namespace
}  // namespace mocapfill
