// Swing clearance's timing (processing/motion/swing_clearance.h): which frames of a leg are
// lifted and how the lift meets keys. Its effect on real fills is measured in foot_plant_test.cc.
#include "processing/motion/swing_clearance.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace mocapfill {
namespace {

constexpr double kFrameS = 1.0 / 30;
constexpr int kFrames = 33;

std::vector<bool> KeysEvery(int step) {
  std::vector<bool> pinned(kFrames, false);
  for (int f = 0; f < kFrames; f += step) pinned[f] = true;
  return pinned;
}

std::vector<bool> FreeBetween(const std::vector<bool>& pinned) {
  std::vector<bool> free(pinned.size());
  for (size_t f = 0; f < pinned.size(); ++f) free[f] = !pinned[f];
  return free;
}

// A synthesised leg (no keys) is lifted by the full shortfall over a stretch that needs it, and
// the lift starts a few frames ahead rather than in one step.
TEST(SwingClearance, SynthesisedLegIsLiftedByTheFullShortfall) {
  std::vector<double> shortfall(kFrames, -0.01);
  for (int f = 12; f <= 20; ++f) shortfall[f] = 0.015;
  const std::vector<bool> none(kFrames, false), free(kFrames, true);
  const std::vector<double> lift = SwingLift(shortfall, free, none, kFrameS, {});
  for (int f = 12; f <= 20; ++f) EXPECT_NEAR(lift[f], 0.015, 1e-12) << f;
  EXPECT_GT(lift[10], 0.0);
  EXPECT_LT(lift[10], lift[11]);
  EXPECT_DOUBLE_EQ(lift[5], 0.0);
  EXPECT_DOUBLE_EQ(lift[27], 0.0);
}

// Keys every 4 frames (30 Hz) carry the swing themselves: nothing is lifted. Every 8 frames the
// gap's middle is lifted fully and the frame next to a key by half; keys and frames a contact
// holds never.
TEST(SwingClearance, DenseKeysLiftNothingSparseKeysRampFromEachKey) {
  const std::vector<double> shortfall(kFrames, 0.01);
  const std::vector<bool> dense = KeysEvery(4), sparse = KeysEvery(8);
  for (double lift : SwingLift(shortfall, FreeBetween(dense), dense, kFrameS, {})) EXPECT_DOUBLE_EQ(lift, 0.0);
  std::vector<bool> free = FreeBetween(sparse);
  free[20] = false;  // a contact holds it
  const std::vector<double> lift = SwingLift(shortfall, free, sparse, kFrameS, {});
  EXPECT_NEAR(lift[12], 0.01, 1e-12);
  EXPECT_NEAR(lift[9], 0.005, 1e-12);
  EXPECT_NEAR(lift[15], 0.005, 1e-12);
  for (int f : {0, 8, 16, 20, 24, 32}) EXPECT_DOUBLE_EQ(lift[f], 0.0) << f;
  SwingClearanceOptions off;
  off.clearance_m = 0.0;
  const std::vector<double> none = SwingLift(shortfall, free, sparse, kFrameS, off);
  EXPECT_EQ(*std::max_element(none.begin(), none.end()), 0.0);
}

// The gap between keys is measured in seconds: keys every 8 frames at 60 Hz are as dense as
// every 4 at 30 Hz.
TEST(SwingClearance, KeyGapsAreMeasuredInSeconds) {
  const std::vector<double> shortfall(kFrames, 0.01);
  const std::vector<bool> keys = KeysEvery(8);
  for (double lift : SwingLift(shortfall, FreeBetween(keys), keys, kFrameS / 2, {})) EXPECT_DOUBLE_EQ(lift, 0.0);
}

}  // namespace
}  // namespace mocapfill
