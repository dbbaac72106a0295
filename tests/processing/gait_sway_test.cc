// The hips' sway over the standing foot (processing/synthesis/gait_sway.h): that it shows which
// foot a captured walk stands on, how two sways are compared, and what ranking synthesised
// legs' candidates by it buys on held-out takes.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <optional>

#include "processing/synthesis/gait_sway.h"
#include "processing/synthesis/ground_contacts.h"
#include "tests/processing/held_out_fill.h"
#include "tests/support/default_db.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// The default database's captured walks (three styles): on the frames where exactly one foot
// stands, the sway points to its side. Positive sway is towards the character's left (+X of the
// heading frame): the hips lean over the left foot when it stands.
TEST(GaitSway, TheHipsSwayOverTheStandingFoot) {
  const MotionDatabase& db = testing::DefaultDb();
  std::vector<std::uint8_t> feet(db.num_joints(), 0);
  for (int j = 0; j < db.num_joints(); ++j) {
    const std::string& name = db.skeleton().name(j);
    feet[j] = name.rfind("Foot_", 0) == 0 || name.rfind("Toes_", 0) == 0;
  }
  Result<DatabaseContacts> contacts = FindDatabaseContacts(db, feet);
  ASSERT_TRUE(contacts.ok()) << contacts.status().message();
  const Eigen::VectorXd sway = DatabaseSway(db, static_cast<int>(std::lround(kSwayHalfWindowS * db.rate_hz())));
  int walks = 0;
  for (int c = 0; c < db.num_clips(); ++c) {
    if (db.clip(c).name.find("walk_") == std::string::npos) continue;
    double sxy = 0.0, sxx = 0.0, syy = 0.0, sx = 0.0, sy = 0.0, n = 0.0;
    for (int f = 0; f < db.clip(c).num_frames; ++f) {
      const int row = db.clip(c).first_frame + f;
      bool left = false, right = false;
      for (size_t k = 0; k < contacts->joints.size(); ++k) {
        const bool down = contacts->down(row, static_cast<Eigen::Index>(k)) > 0.5f;
        const std::string& name = db.skeleton().name(contacts->joints[k]);
        left = left || (down && EndsWith(name, "_L"));
        right = right || (down && EndsWith(name, "_R"));
      }
      if (left == right) continue;
      const double x = left ? 1.0 : -1.0, y = sway[row];
      sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y, n += 1.0;
    }
    ASSERT_GE(n, 20.0) << db.clip(c).name;
    const double correlation = (sxy - sx * sy / n) / std::sqrt((sxx - sx * sx / n) * (syy - sy * sy / n));
    std::printf("%s: sway against the standing foot (left +1, right -1) correlates %.3f over %.0f frames\n",
                db.clip(c).name.c_str(), correlation, n);
    EXPECT_GT(correlation, 0.5) << db.clip(c).name;
    ++walks;
  }
  EXPECT_GE(walks, 3);
}

// Agreement is the cosine of 8 samples taken evenly over each stretch, whatever their lengths.
TEST(GaitSway, AgreementIsTheCosineOfTheStretchedSways) {
  Eigen::VectorXd a(31), b(61);
  for (int f = 0; f < 31; ++f) a[f] = std::sin(2.0 * M_PI * f / 30.0);
  for (int f = 0; f < 61; ++f) b[f] = 0.03 * std::sin(2.0 * M_PI * f / 60.0);
  // Samples fall on whole frames: a stretched sample may land half a frame off.
  EXPECT_NEAR(SwayAgreement(a, 0, 30, b, 0, 60), 1.0, 1e-3);  // one stride, stretched twice as long
  EXPECT_NEAR(SwayAgreement(a, 0, 30, -b, 0, 60), -1.0, 1e-3);
  EXPECT_NEAR(SwayAgreement(a, 0, 15, b, 30, 60), -1.0, 1e-3);  // the first step against the second
  EXPECT_EQ(SwayAgreement(a, 0, 30, Eigen::VectorXd::Zero(61), 0, 60), 0.0);
}

// Only the root keyed every 8 frames on the locomotion of a style the database lacks (childish,
// whose synthesised legs stepped most often in anti-phase): the
// synthesised legs' candidates that sway over the other foot rank lower where the root moves,
// and the fill's feet stand more where the capture's stood (less skating on the capture's
// contacts); the legs come nearer the capture too.
TEST(GaitSway, SynthesisedLegsStepOnTheFootTheHipsSwayOver) {
  MOCAPFILL_REQUIRE_CORPUS();
  FillOptions before;
  before.leg_sway_weight = 0.0;  // matched without the sway
  const std::optional<testing::VariantScores> scores = testing::ScoreBeforeAndNow(
      "childish", "root", {"walk_childish_001", "walk_childish_002", "walk-back_childish_001", "walk-left_childish_001",
                          "walk-right_childish_001", "run_childish_001", "dash_childish_001"},
      before);
  ASSERT_TRUE(scores);
  EXPECT_LT(scores->skate_cm_per_s[1], 0.95 * scores->skate_cm_per_s[0]);  // measured 36.02 against 39.53 cm/s
  EXPECT_LT(scores->mpjpe_cm[1], 0.99 * scores->mpjpe_cm[0]);              // measured 7.180 against 7.370 cm
}

// The upper body keyed every 8 frames on the slow walks (0.45 - 0.6 m/s at the hips) of a style
// the database lacks (not-confident): their synthesised legs stepped in anti-phase, the left
// foot planted while the capture's swung (walking left against the tuning half: 110 cm/s on
// the capture's contacts, 45 now), until the sway ranked candidates below 0.6 m/s too.
TEST(GaitSway, SlowWalksStepOnTheFootTheHipsSwayOver) {
  MOCAPFILL_REQUIRE_CORPUS();
  FillOptions before;
  before.sway_speed_m_per_s = 0.6;  // brisk walks only
  const std::optional<testing::VariantScores> scores = testing::ScoreBeforeAndNow(
      "not-confident", "upper-body",
      {"walk_not-confident_001", "walk-left_not-confident_001", "walk-back_not-confident_001"}, before);
  ASSERT_TRUE(scores);
  EXPECT_LT(scores->skate_cm_per_s[1], 0.9 * scores->skate_cm_per_s[0]);  // measured 32.10 against 37.28 cm/s
  EXPECT_LT(scores->mpjpe_cm[1], 0.95 * scores->mpjpe_cm[0]);              // measured 6.892 against 7.612 cm
}

}  // namespace
}  // namespace mocapfill
