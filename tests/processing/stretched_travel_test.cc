// The root's velocities matched as a take moves them once stretched onto the sketch's
// fragment (FragmentFillOptions::stretched_travel, fragment_matching.h).
#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "processing/synthesis/fragment_matching.h"
#include "tests/processing/held_out_fill.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

// A database fragment twice the sketch fragment's length plays at twice its captured speed.
TEST(StretchedTravel, SpeedScalesWithTheStretch) {
  const DbFragment take{0, 0, 10, 30, true};
  EXPECT_DOUBLE_EQ(StretchSpeedRatio(take, SketchFragment{0, 10, true}), 2.0);
  EXPECT_DOUBLE_EQ(StretchSpeedRatio(take, SketchFragment{5, 45, true}), 0.5);
}

// Only the root keyed every 8 frames on the locomotion of a style the database lacks, whose
// walks are the slowest (not-confident, 0.45 - 0.6 m/s at the hips): the synthesised legs come
// from takes that step at the sketch's pace once stretched onto it rather than from takes
// that stand, so the feet slide less on the capture's contacts and the legs lie nearer it.
TEST(StretchedTravel, SynthesisedLegsStepAtTheSketchsPace) {
  MOCAPFILL_REQUIRE_CORPUS();
  FillOptions before;
  before.stretched_travel = false;  // matched at the takes' captured speed
  const std::string style = "not-confident";
  const std::optional<testing::VariantScores> scores = testing::ScoreBeforeAndNow(
      style, "root",
      {"walk_" + style + "_001", "walk-back_" + style + "_001", "walk-left_" + style + "_001",
       "walk-right_" + style + "_001", "run_" + style + "_001", "dash_" + style + "_001"},
      before);
  ASSERT_TRUE(scores);
  EXPECT_LT(scores->skate_cm_per_s[1], 0.95 * scores->skate_cm_per_s[0]);  // measured 30.77 against 35.43 cm/s
  EXPECT_LT(scores->mpjpe_cm[1], 0.99 * scores->mpjpe_cm[0]);              // measured 9.200 against 9.428 cm
}

}  // namespace
}  // namespace mocapfill
