// Synthesised arms reaching where the blended takes have their hands
// (processing/synthesis/limb_reach.h): the limbs found on the database's rig, the two-bone
// reach on captured frames, and what it buys the fill on held-out takes.
#include <gtest/gtest.h>

#include <cstdio>

#include "formats/motion_io.h"
#include "processing/core/rotation.h"
#include "processing/evaluation/metrics.h"
#include "processing/evaluation/scenarios.h"
#include "processing/evaluation/sketch_maker.h"
#include "processing/fill/fill_engine.h"
#include "processing/synthesis/limb_reach.h"
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
  Result<SketchScenario> scenario = FindSketchScenario("legs8");
  ASSERT_TRUE(scenario.ok());
  const MotionDatabase& db = testing::BandaiDbWithout("proud");
  FillEngine engine(db);
  std::map<std::string, std::map<double, double>> mpjpe;
  const std::pair<const char*, const char*> takes[] = {
      {"walk_proud_001", "locomotion"}, {"run_proud_001", "locomotion"}, {"walk-left_proud_001", "locomotion"},
      {"bow_proud_001", "gestures"},    {"bye_proud_001", "gestures"},   {"byebye_proud_001", "gestures"},
      {"guide_proud_001", "gestures"}};
  for (const auto& [take, kind] : takes) {
    Result<Scene> truth = ImportFile(testing::DataPath(std::string("bandai-namco-1/data/dataset-1_") + take + ".bvh"));
    ASSERT_TRUE(truth.ok()) << take;
    Result<MotionClip> sketch = MakeSketch(db.skeleton(), truth->clips[0], scenario->sketch);
    ASSERT_TRUE(sketch.ok()) << sketch.status().message();
    for (double reach : {0.0, 0.5}) {
      FillOptions options;
      options.limb_reach = reach;
      Result<FillResult> r = engine.Fill(*sketch, options);
      ASSERT_TRUE(r.ok()) << r.status().message();
      Result<FillMetrics> m = ScoreFill(db.skeleton(), truth->clips[0], *sketch, r->clip, db.root_joint());
      ASSERT_TRUE(m.ok());
      mpjpe[kind][reach] += m->mpjpe_unkeyed_cm;
      EXPECT_LT(m->key_error_max_deg, 0.01);
    }
  }
  for (const auto& [kind, by_reach] : mpjpe)
    std::printf("%s: unkeyed MPJPE summed %.3f cm as the rotations put the hands, %.3f cm reaching half way\n",
                kind.c_str(), by_reach.at(0.0), by_reach.at(0.5));
  EXPECT_LT(mpjpe["locomotion"][0.5], 0.985 * mpjpe["locomotion"][0.0]);  // measured 16.751 against 17.271
  EXPECT_LT(mpjpe["gestures"][0.5], 0.95 * mpjpe["gestures"][0.0]);  // measured 39.127 against 43.037
}

}  // namespace
}  // namespace mocapfill
