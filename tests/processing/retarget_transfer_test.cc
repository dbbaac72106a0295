// Rest-pose-aware retargeting on real rigs: round trips between the Bandai-Namco, CMU and
// Geno skeletons keep every mapped bone's world direction, one rig retargets onto itself
// unchanged, and Geno's two rest poses (A-pose and T-pose first frames) give one result.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

#include "formats/motion_io.h"
#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "processing/retargeting/retarget.h"
#include "tests/support/test_paths.h"
#include "tests/support/bone_directions.h"

namespace mocapfill {
namespace {

using testing::BoneSegments;
using testing::LimbSegments;
using testing::MaxDirectionErrorDeg;

struct LoadedRig {
  Scene scene;
  RigMapping mapping;
  HumanoidRig rig;
};

LoadedRig Load(const std::string& path, RestSource rest = RestSource::kAuto) {
  Result<Scene> scene = ImportFile(path);
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  const Skeleton& s = scene->skeleton;
  Result<RigMapping> mapping = MapHumanoid(s, ZeroPose(s).WorldPositions(s));
  EXPECT_TRUE(mapping.ok()) << mapping.status().message();
  Result<RigRest> chosen = ChooseRest(*scene, *mapping, rest);
  EXPECT_TRUE(chosen.ok()) << chosen.status().message();
  Result<HumanoidRig> rig = HumanoidRig::Make(s, *mapping, *chosen);
  EXPECT_TRUE(rig.ok()) << rig.status().message();
  return {std::move(*scene), *mapping, std::move(*rig)};
}

TEST(RetargetTransfer, SameRigCopiesRotations) {
  const LoadedRig bandai = Load(testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"));
  const MotionClip& clip = bandai.scene.clips[0];
  const MotionClip out = RetargetClip(bandai.rig, clip, bandai.rig);
  double worst = 0.0, worst_m = 0.0;
  for (int f = 0; f < clip.num_frames; ++f)
    for (int j = 0; j < clip.num_joints; ++j) {
      worst = std::max(worst, GeodesicAngle(clip.rotation(f, j), out.rotation(f, j)) * kDegPerRad);
      worst_m = std::max(worst_m, (clip.translation(f, j) - out.translation(f, j)).norm());
    }
  EXPECT_LT(worst, 1e-6);
  EXPECT_LT(worst_m, 1e-9);
}

// Largest angle between the two clips' rotations of `joints`, over every frame (degrees).
double WorstRotationDeg(const MotionClip& a, const MotionClip& b, const std::vector<int>& joints) {
  double worst = 0.0;
  for (int f = 0; f < a.num_frames; ++f)
    for (int j : joints) worst = std::max(worst, GeodesicAngle(a.rotation(f, j), b.rotation(f, j)) * kDegPerRad);
  return worst;
}

// A bone's T-pose twist is its twist relative to its parent in the rest: a rest whose hips
// are turned against the upper body (a walking frame or mean pose often is) leaves the legs'
// T-pose as it was, so retargeting between the two rests of one rig keeps the legs' local
// rotations. (Measured against world axes, the legs would take up the turn as a twist.)
TEST(RetargetTransfer, HipsTurnedInTheRestDoNotTwistTheLegs) {
  const LoadedRig bandai = Load(testing::FixturePath("default_db/dataset-1_walk_normal_001.bvh"));
  const Skeleton& s = bandai.scene.skeleton;
  const int hips = bandai.mapping.joint(HumanoidBone::kHips), spine = bandai.mapping.joint(HumanoidBone::kSpine);
  ASSERT_EQ(s.parent(spine), hips);
  RigRest turned = bandai.rig.rest();
  const std::vector<Eigen::Quaterniond> world = turned.WorldRotations(s);
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(25.0 * kRadPerDeg, Eigen::Vector3d::UnitY()));
  // Hips turned 25 degrees about the vertical, the spine turned back: the upper body faces as before.
  const Eigen::Quaterniond parent = world[hips] * turned.local_rotations[hips].conjugate();
  turned.local_rotations[hips] = (parent.conjugate() * turn * world[hips]).normalized();
  turned.local_rotations[spine] = ((turn * world[hips]).conjugate() * world[spine]).normalized();
  Result<HumanoidRig> rig = HumanoidRig::Make(s, bandai.mapping, turned);
  ASSERT_TRUE(rig.ok()) << rig.status().message();
  const MotionClip out = RetargetClip(bandai.rig, bandai.scene.clips[0], *rig);
  std::vector<int> legs;
  for (HumanoidBone b : {HumanoidBone::kLeftUpperLeg, HumanoidBone::kLeftLowerLeg, HumanoidBone::kLeftFoot,
                         HumanoidBone::kRightUpperLeg, HumanoidBone::kRightLowerLeg, HumanoidBone::kRightFoot})
    legs.push_back(bandai.mapping.joint(b));
  const double worst = WorstRotationDeg(bandai.scene.clips[0], out, legs);
  std::printf("legs' local rotations after retargeting onto the rest with turned hips: worst %.2g deg\n", worst);
  EXPECT_LT(worst, 0.01);
}

// The root's scale is the hips' height with straight legs, which bone lengths fix: the rests
// of one rig taken from two takes (a walk's and a run's mean pose, a walk's first frame) give
// the same hip height, however the knees bend in them.
TEST(RetargetTransfer, HipHeightDoesNotFollowTheRestsKneeBend) {
  std::vector<double> heights;
  for (const char* take : {"dataset-1_walk_normal_001.bvh", "dataset-1_run_normal_001.bvh"})
    for (RestSource rest : {RestSource::kMean, RestSource::kFirstFrame})
      heights.push_back(Load(testing::FixturePath(std::string("default_db/") + take), rest).rig.hip_height_m());
  const auto [low, high] = std::minmax_element(heights.begin(), heights.end());
  std::printf("Bandai-Namco hip height from four rests: %.4f to %.4f m\n", *low, *high);
  EXPECT_GT(*low, 0.8);
  EXPECT_LT(*high - *low, 0.003);
}

TEST(RetargetTransfer, BandaiToCmuAndBackKeepsDirections) {
  const LoadedRig bandai = Load(testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"));
  const LoadedRig cmu = Load(testing::FixturePath("bvh/cmu_01_01_short.bvh"));
  const MotionClip& clip = bandai.scene.clips[0];
  const MotionClip on_cmu = RetargetClip(bandai.rig, clip, cmu.rig);
  ASSERT_TRUE(on_cmu.Validate(cmu.scene.skeleton).ok());
  // In the hips' frame, limbs and the head point as on the Bandai rig. (The trunk from hips
  // to neck bends over other joints on each rig, so only round trips compare it.)
  const double limbs = MaxDirectionErrorDeg(bandai.rig, clip, cmu.rig, on_cmu, LimbSegments());
  const MotionClip back = RetargetClip(cmu.rig, on_cmu, bandai.rig);
  const double bones = MaxDirectionErrorDeg(bandai.rig, clip, bandai.rig, back, BoneSegments(bandai.mapping));
  const double upper = MaxDirectionErrorDeg(bandai.rig, clip, bandai.rig, back, testing::UpperBodySegments());
  std::printf("Bandai -> CMU: limbs %.2e deg; and back: bones %.2e deg, upper body %.2e deg\n", limbs, bones, upper);
  EXPECT_LT(limbs, 0.1);
  EXPECT_LT(bones, 0.1);
  EXPECT_LT(upper, 0.1);
}

TEST(RetargetTransfer, GenoBindAndStanceFirstFramesAgree) {
  MOCAPFILL_REQUIRE_CORPUS();
  const LoadedRig bandai = Load(testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"));
  const LoadedRig bind = Load(testing::DataPath("geno/Geno_bind.bvh"), RestSource::kFirstFrame);
  const LoadedRig stance = Load(testing::DataPath("geno/Geno_stance.bvh"), RestSource::kFirstFrame);
  const MotionClip& clip = bandai.scene.clips[0];
  const MotionClip via_bind = RetargetClip(bandai.rig, clip, bind.rig);
  const MotionClip via_stance = RetargetClip(bandai.rig, clip, stance.rig);
  // One skeleton, two rest poses (A-pose and T-pose): the same world bone directions.
  const double rests = MaxDirectionErrorDeg(bind.rig, via_bind, stance.rig, via_stance, BoneSegments(bind.mapping));
  // And the limbs point as on the Bandai rig.
  const double limbs = MaxDirectionErrorDeg(bandai.rig, clip, bind.rig, via_bind, LimbSegments());
  const MotionClip back = RetargetClip(bind.rig, via_bind, bandai.rig);
  const double bones = MaxDirectionErrorDeg(bandai.rig, clip, bandai.rig, back, BoneSegments(bandai.mapping));
  const double upper = MaxDirectionErrorDeg(bandai.rig, clip, bandai.rig, back, testing::UpperBodySegments());
  std::printf("Geno A-pose against T-pose rest %.2e deg; Bandai -> Geno limbs %.2e deg; and back: bones %.2e deg, "
              "upper body %.2e deg\n", rests, limbs, bones, upper);
  EXPECT_LT(rests, 0.1);
  EXPECT_LT(limbs, 0.1);
  EXPECT_LT(bones, 0.1);
  EXPECT_LT(upper, 0.1);
}

}  // namespace
}  // namespace mocapfill
