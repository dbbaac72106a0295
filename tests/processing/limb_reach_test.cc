// Synthesised arms reaching where the blended takes have their hands
// (processing/synthesis/limb_reach.h): the limbs found on the database's rig, the two-bone
// reach on captured frames, and what it buys the fill on held-out takes.
#include <gtest/gtest.h>

#include <cstdio>

#include "formats/motion_io.h"
#include "processing/core/rotation.h"
#include "processing/evaluation/metrics.h"
#include "processing/fill/fill_engine.h"
#include "processing/synthesis/limb_reach.h"
#include "tests/processing/held_out_fill.h"
#include "tests/support/default_db.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

// Every 13th frame of the default database, as fill channels (rows) and as reach targets.
struct CapturedArms {
  ArmReach prepared;
  std::vector<Limb> limbs;
  Eigen::MatrixXd channels;
  Eigen::MatrixXd reach;
};

CapturedArms CapturedArmsEvery(int step, int shift) {
  const MotionDatabase& db = testing::DefaultDb();
  CapturedArms c{PrepareArmReach(db), {}, {}, {}};
  c.limbs = c.prepared.arms;
  const Eigen::MatrixXf& table = c.prepared.table;
  const int rows = (db.num_frames() - shift) / step;
  c.channels.resize(rows, db.num_channels());
  c.reach.resize(rows, table.cols());
  for (int i = 0; i < rows; ++i) {
    c.channels.row(i) = db.signals().row(i * step).cast<double>();
    c.reach.row(i) = table.row(i * step + shift).cast<double>();
  }
  return c;
}

// Where the channels put each limb's tip (as ArmReach::table has it for the database's frames).
Eigen::Vector3d TipOf(const MotionDatabase& db, const Limb& limb, const Eigen::MatrixXd& channels, int row) {
  auto local = [&](int j) {
    return Eigen::Quaterniond(db.joint_means()[j] * ExpMap(channels.row(row).segment<3>(3 * j).transpose()));
  };
  const Skeleton& s = db.skeleton();
  return local(limb.upper) * (s.joint(limb.lower).rest_translation + local(limb.lower) * s.joint(limb.end).rest_translation);
}

std::vector<std::string> Named(const Skeleton& s, const std::vector<Limb>& limbs) {
  std::vector<std::string> names;
  for (const Limb& limb : limbs) names.push_back(s.name(limb.upper) + ">" + s.name(limb.lower) + ">" + s.name(limb.end));
  return names;
}

std::vector<Limb> Picked(const std::vector<Limb>& limbs, const std::vector<int>& which) {
  std::vector<Limb> picked;
  for (int i : which) picked.push_back(limbs[i]);
  return picked;
}

// Arms by the rig's humanoid mapping, on the database's rig and on CMU's (whose hands carry
// finger joints and whose head hangs on two neck joints: a rule by chain ends alone found no
// arm there and took the neck for one).
TEST(LimbReach, ArmsOfTheDatabaseRigAndOfCmu) {
  const Skeleton& s = testing::DefaultDb().skeleton();
  const std::vector<Limb> arms = ArmsOf(s);
  EXPECT_EQ(Named(s, arms), (std::vector<std::string>{"UpperArm_L>LowerArm_L>Hand_L", "UpperArm_R>LowerArm_R>Hand_R"}));
  const std::vector<int> left_group = {*s.Find("Shoulder_L"), *s.Find("UpperArm_L"), *s.Find("LowerArm_L"),
                                       *s.Find("Hand_L")};
  EXPECT_EQ(Named(s, Picked(arms, LimbsWithin(arms, left_group))),
            (std::vector<std::string>{"UpperArm_L>LowerArm_L>Hand_L"}));
  EXPECT_TRUE(LimbsWithin(arms, {*s.Find("UpperArm_L"), *s.Find("LowerArm_L")}).empty());

  Result<Scene> cmu = ImportFile(testing::FixturePath("bvh/cmu_01_01_short.bvh"));
  ASSERT_TRUE(cmu.ok()) << cmu.status().message();
  EXPECT_EQ(Named(cmu->skeleton, ArmsOf(cmu->skeleton)),
            (std::vector<std::string>{"LeftArm>LeftForeArm>LeftHand", "RightArm>RightForeArm>RightHand"}));
}

// Asked to reach where its own hand is, a captured arm stays as it is; asked to reach where the
// hand of another captured frame is, it gets there exactly (bent about its elbow's hinge, turned
// at the shoulder) and the hand keeps its own rotation; half way is half way.
TEST(LimbReach, CapturedArmsReachCapturedHands) {
  const MotionDatabase& db = testing::DefaultDb();
  const CapturedArms same = CapturedArmsEvery(13, 0);
  ASSERT_GT(same.channels.rows(), 100);
  ASSERT_EQ(same.limbs.size(), 2u);  // both arms: reached as {0, 1} below
  Eigen::MatrixXd out = same.channels;
  ReachLimbs(db, same.prepared, {0, 1}, same.reach, 1.0, out);

  // Measured 0.0029 rad: the float table's rounding, on nearly straight captured arms, and arms
  // captured a hair past straight about the hinge, which the reach bends back to the elbow's side.
  EXPECT_LT((out - same.channels).cwiseAbs().maxCoeff(), 5e-3);

  const CapturedArms other = CapturedArmsEvery(13, 7);
  for (double strength : {1.0, 0.5}) {
    out = other.channels;
    ReachLimbs(db, other.prepared, {0, 1}, other.reach, strength, out);
    double worst = 0.0, moved = 0.0;
    for (size_t i = 0; i < other.limbs.size(); ++i) {
      const Limb& limb = other.limbs[i];
      for (int r = 0; r < out.rows(); ++r) {
        const Eigen::Vector3d before = TipOf(db, limb, other.channels, r);
        const Eigen::Vector3d want = before + strength * (other.reach.row(r).segment<3>(3 * i).transpose() - before);

        worst = std::max(worst, (TipOf(db, limb, out, r) - want).norm());
        moved = std::max(moved, (TipOf(db, limb, out, r) - before).norm());
        ASSERT_EQ(out.row(r).segment<3>(3 * limb.end), other.channels.row(r).segment<3>(3 * limb.end));
      }
    }
    std::printf("strength %.1f: tips within %.2g m of their targets, moved up to %.3f m\n", strength, worst, moved);
    EXPECT_LT(worst, 1e-5);
    EXPECT_GT(moved, 0.1);
  }
}

// Root and legs keyed every 8 frames on takes of a style the database lacks (leave-one-style-out,
// as eval does): the synthesised arms reaching half way to where the blended takes have their
// hands lower the error of the synthesised joints, on walks and on gestures.
TEST(LimbReach, LowersTheErrorOfHeldOutTakes) {
  MOCAPFILL_REQUIRE_CORPUS();
  const MotionDatabase& db = testing::BandaiDbWithout("proud");
  FillEngine engine(db);
  std::vector<FillOptions> variants(2);
  variants[0].limb_reach = 0.0;
  variants[1].limb_reach = 0.5;
  // The arms as blended: with their swing scaled by 1.2 the reach buys less on locomotion
  // (16.615 against 16.758 cm; gestures 39.195 against 41.567).
  for (FillOptions& v : variants) v.swing_gain = 1.0;
  Result<testing::ProudSums> sums = testing::FillProudTakesByCategory(engine, db, variants);
  ASSERT_TRUE(sums.ok()) << sums.status().message();
  const std::vector<double>& locomotion = sums->locomotion;
  const std::vector<double>& gestures = sums->gestures;
  EXPECT_LT(sums->key_error_max_deg, 0.01);
  std::printf("locomotion: unkeyed MPJPE summed %.3f cm as the rotations put the hands, %.3f cm reaching half way\n",
              locomotion[0], locomotion[1]);
  std::printf("gestures: unkeyed MPJPE summed %.3f cm as the rotations put the hands, %.3f cm reaching half way\n",
              gestures[0], gestures[1]);
  // Measured 16.409 against 16.614 and 39.089 against 41.472 (16.751 / 17.271 and 39.127 /
  // 43.037 before the blend moved towards the candidates' median posture).
  EXPECT_LT(locomotion[1], 0.99 * locomotion[0]);
  EXPECT_LT(gestures[1], 0.95 * gestures[0]);
}

}  // namespace
}  // namespace mocapfill
