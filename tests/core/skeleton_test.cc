#include "processing/core/skeleton.h"

#include <gtest/gtest.h>

#include <limits>

#include "processing/core/kinematics.h"
#include "processing/core/motion_clip.h"
#include "processing/core/rotation.h"

namespace mocapfill {
namespace {

std::vector<Joint> Chain() {
  std::vector<Joint> joints(3);
  joints[0].name = "root";
  joints[1].name = "mid";
  joints[1].parent = 0;
  joints[1].rest_translation = {0, 1, 0};
  joints[2].name = "tip";
  joints[2].parent = 1;
  joints[2].rest_translation = {0, 1, 0};
  return joints;
}

TEST(Skeleton, BuildRejectsEveryInvalidInput) {
  EXPECT_FALSE(Skeleton::Build({}).ok());
  auto dup = Chain();
  dup[2].name = "mid";
  EXPECT_EQ(Skeleton::Build(dup).status().code(), ErrorCode::kInvalidData);
  auto empty = Chain();
  empty[1].name.clear();
  EXPECT_FALSE(Skeleton::Build(empty).ok());
  auto order = Chain();
  order[1].parent = 2;
  EXPECT_FALSE(Skeleton::Build(order).ok());
  auto nan = Chain();
  nan[1].rest_translation.x() = std::nan("");
  EXPECT_FALSE(Skeleton::Build(nan).ok());
}

TEST(Skeleton, FindsJointsAndMeasuresHierarchyDistance) {
  const Skeleton s = *Skeleton::Build(Chain());
  EXPECT_EQ(*s.Find("tip"), 2);
  EXPECT_FALSE(s.Find("nope"));
  EXPECT_EQ(s.HierarchyDistance(0, 2), 2);
  EXPECT_EQ(s.HierarchyDistance(2, 1), 1);
  EXPECT_EQ(s.Roots(), std::vector<int>{0});
  EXPECT_EQ(s.Children(0), std::vector<int>{1});
}

TEST(Kinematics, RotatingTheRootSwingsTheChain) {
  const Skeleton s = *Skeleton::Build(Chain());
  MotionClip clip = MotionClip::RestPose(s, 1, 30.0);
  clip.rotation(0, 0) = Eigen::Quaterniond(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()));
  const auto positions = ComputeWorldPositions(s, clip);
  EXPECT_LT((positions[2] - Eigen::Vector3d(-2, 0, 0)).norm(), 1e-12);
  EXPECT_TRUE(clip.Validate(s).ok());
  EXPECT_NEAR(RestPoseExtent(s, 1), 2.0, 1e-12);
}

// Validate's fast acceptance (squared norms, x - x for finiteness) must reject exactly what
// the per-value checks reject, with the same messages.
TEST(MotionClip, ValidateRejectsNonFiniteAndNonUnitValuesByName) {
  const Skeleton s = *Skeleton::Build(Chain());
  MotionClip clip = MotionClip::RestPose(s, 4, 30.0);
  clip.translation(2, 1).y() = std::numeric_limits<double>::quiet_NaN();
  Status status = clip.Validate(s);
  EXPECT_NE(status.message().find("non-finite value at frame 2, joint 'mid'"), std::string::npos) << status.message();
  clip.translation(2, 1).y() = 1.0;
  clip.rotation(3, 2).coeffs().x() = std::numeric_limits<double>::infinity();
  status = clip.Validate(s);
  EXPECT_NE(status.message().find("non-finite value at frame 3, joint 'tip'"), std::string::npos) << status.message();
  clip.rotation(3, 2) = Eigen::Quaterniond(1.0 + 1.2e-6, 0.0, 0.0, 0.0);  // 1.2e-6 off unit: rejected
  status = clip.Validate(s);
  EXPECT_NE(status.message().find("non-unit rotation"), std::string::npos) << status.message();
  clip.rotation(3, 2) = Eigen::Quaterniond(1.0 - 0.99e-6, 0.0, 0.0, 0.0);  // within 1e-6: accepted
  EXPECT_TRUE(clip.Validate(s).ok());
  clip.translation(0, 0).x() = 1e308;  // huge but finite (x - x stays 0)
  EXPECT_TRUE(clip.Validate(s).ok());
}

}  // namespace
}  // namespace mocapfill
