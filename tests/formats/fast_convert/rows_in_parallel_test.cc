// The two-thread MOTION parser (formats/fast_convert/rows_in_parallel.h) against the serial loop: large
// texts made by repeating the rows of real captures must give bit-identical clips, and
// every irregular case (bad value, wrong frame count, CRLF line ends) must end in exactly
// the serial loop's error or warnings.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "formats/fast_convert/rows_in_parallel.h"
#include "formats/bvh/bvh_reader.h"
#include "tests/formats/bvh_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::FixturePath;
using testing::EnlargeMotion;
using testing::ReadText;
using fast_convert::kParallelRowsMinBytes;

Result<Scene> Read(const std::string& text, int threads) {
  return ReadBvh(text, "big.bvh", {}, threads == 1 ? nullptr : &fast_convert::ParseRowsIntoClip);
}

void ExpectBitIdentical(const Scene& a, const Scene& b) {
  const MotionClip& x = a.clips.at(0);
  const MotionClip& y = b.clips.at(0);
  ASSERT_EQ(x.num_frames, y.num_frames);
  ASSERT_EQ(x.rotations.size(), y.rotations.size());
  ASSERT_EQ(x.translations.size(), y.translations.size());
  EXPECT_EQ(0, std::memcmp(x.rotations.data(), y.rotations.data(), x.rotations.size() * sizeof(x.rotations[0])));
  EXPECT_EQ(0, std::memcmp(x.translations.data(), y.translations.data(),
                           x.translations.size() * sizeof(x.translations[0])));
  EXPECT_EQ(a.warnings, b.warnings);
}

class BvhParallel : public ::testing::TestWithParam<const char*> {};

TEST_P(BvhParallel, LargeMotionIsBitIdenticalToTheSerialParse) {
  const std::string text = EnlargeMotion(ReadText(FixturePath(std::string("bvh/") + GetParam())),
                                   4 * kParallelRowsMinBytes);
  const Result<Scene> serial = Read(text, 1);
  const Result<Scene> parallel = Read(text, 0);
  ASSERT_TRUE(serial.ok()) << serial.status().message();
  ASSERT_TRUE(parallel.ok()) << parallel.status().message();
  EXPECT_GT(serial->clips.at(0).num_frames, 300);
  ExpectBitIdentical(*serial, *parallel);
}

TEST_P(BvhParallel, FrameCountMismatchGivesTheSerialWarnings) {
  for (int delta : {-7, +7}) {
    const std::string text = EnlargeMotion(ReadText(FixturePath(std::string("bvh/") + GetParam())),
                                     4 * kParallelRowsMinBytes, delta);
    const Result<Scene> serial = Read(text, 1);
    const Result<Scene> parallel = Read(text, 0);
    ASSERT_EQ(serial.ok(), parallel.ok()) << "delta " << delta;
    if (!serial.ok()) {
      EXPECT_EQ(serial.status().message(), parallel.status().message());
      continue;
    }
    EXPECT_FALSE(serial->warnings.empty()) << "delta " << delta;
    ExpectBitIdentical(*serial, *parallel);
  }
}

INSTANTIATE_TEST_SUITE_P(Fixtures, BvhParallel,
                         ::testing::Values("cmu_01_01_short.bvh", "bandai_walk_normal_001_short.bvh",
                                           "cmu_crlf.bvh", "cmu_mixed_orders.bvh"));

// A bad value late in the second half: the parallel attempt gives up and the error names
// the same line and column as the serial parse.
TEST(BvhParallelErrors, BadValueInTheSecondHalfReportsTheSameLine) {
  std::string text = EnlargeMotion(ReadText(FixturePath("bvh/cmu_01_01_short.bvh")), 4 * kParallelRowsMinBytes);
  const size_t at = text.rfind('\n', text.size() - 2000);
  text.insert(at + 1, "nan ");
  const Result<Scene> serial = Read(text, 1);
  const Result<Scene> parallel = Read(text, 0);
  ASSERT_FALSE(serial.ok());
  ASSERT_FALSE(parallel.ok());
  EXPECT_EQ(serial.status().message(), parallel.status().message());
  EXPECT_NE(parallel.status().message().find("big.bvh:"), std::string::npos) << parallel.status().message();
}

}  // namespace
}  // namespace mocapfill
