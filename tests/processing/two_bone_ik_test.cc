// Two-bone IK on real legs and arms: the end lands on reachable targets exactly, bones keep
// their lengths, the end keeps its world orientation, and out-of-reach targets are met as
// nearly as the limb stretches or folds.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "formats/motion_io.h"
#include "processing/core/kinematics.h"
#include "processing/motion/two_bone_ik.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

struct Limb {
  const char* upper;
  const char* lower;
  const char* end;
};

void ExpectSolves(const std::string& file, const std::vector<Limb>& limbs) {
  SCOPED_TRACE(file);
  Result<Scene> scene = ImportFile(file);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const Skeleton& s = scene->skeleton;
  std::mt19937 random(7);
  std::uniform_real_distribution<double> offset(-0.15, 0.15);
  int solved = 0;
  for (const Limb& limb : limbs) {
    const TwoBoneChain chain{*s.Find(limb.upper), *s.Find(limb.lower), *s.Find(limb.end)};
    for (int f = 0; f < scene->clips[0].num_frames; f += 2) {
      MotionClip clip = scene->clips[0];
      WorldPose before, after;
      ComputeWorldPose(s, clip, f, before);
      // Drawn one by one: the order of a constructor's arguments is up to the compiler.
      Eigen::Vector3d shift;
      for (int axis = 0; axis < 3; ++axis) shift[axis] = offset(random);
      const Eigen::Vector3d target = before.positions[chain.end] + shift;
      const TwoBoneSolution solution = SolveTwoBoneIk(s, before, chain, target);
      clip.rotation(f, chain.upper) = solution.upper;
      clip.rotation(f, chain.lower) = solution.lower;
      clip.rotation(f, chain.end) = solution.end;
      ComputeWorldPose(s, clip, f, after);
      const double upper_length = (before.positions[chain.lower] - before.positions[chain.upper]).norm();
      const double lower_length = (before.positions[chain.end] - before.positions[chain.lower]).norm();
      // Reachable between the folded span |upper - lower| and the straight span upper + lower.
      const double distance = (target - before.positions[chain.upper]).norm();
      if (distance < 0.999 * (upper_length + lower_length) && distance > 1.001 * std::abs(upper_length - lower_length)) {
        EXPECT_LT((after.positions[chain.end] - target).norm(), 1e-9) << limb.end << " frame " << f;
        EXPECT_LT(solution.miss_m, 1e-9);
        ++solved;
      } else {
        EXPECT_NEAR((after.positions[chain.end] - target).norm(), solution.miss_m, 1e-6);
      }
      EXPECT_NEAR((after.positions[chain.lower] - after.positions[chain.upper]).norm(),
                  (before.positions[chain.lower] - before.positions[chain.upper]).norm(), 1e-12);
      EXPECT_NEAR((after.positions[chain.end] - after.positions[chain.lower]).norm(),
                  (before.positions[chain.end] - before.positions[chain.lower]).norm(), 1e-12);
      EXPECT_LT(after.rotations[chain.end].angularDistance(before.rotations[chain.end]), 1e-9);
      EXPECT_LT((after.positions[chain.upper] - before.positions[chain.upper]).norm(), 1e-12);
    }
  }
  EXPECT_GT(solved, 10);
}

TEST(TwoBoneIk, LegsAndArmsOfRealRigs) {
  ExpectSolves(testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"),
               {{"UpperLeg_L", "LowerLeg_L", "Foot_L"}, {"UpperArm_R", "LowerArm_R", "Hand_R"}});
  ExpectSolves(testing::FixturePath("bvh/cmu_01_01_short.bvh"),
               {{"RightUpLeg", "RightLeg", "RightFoot"}, {"LeftArm", "LeftForeArm", "LeftHand"}});
}

}  // namespace
}  // namespace mocapfill
