#include "processing/filtering/motion_filter.h"

#include <gtest/gtest.h>

#include "tests/processing/synthetic_motion.h"

namespace mocapfill {
namespace {

TEST(MultiresFilter, ValidateRejectsBadOptions) {
  const Skeleton skeleton = testing::WalkerSkeleton();
  const MotionClip clip = testing::WalkerClip(skeleton, {});
  MultiresFilterOptions options;
  options.gains.band_gains = {1.0, NAN};
  EXPECT_EQ(MultiresFilter(skeleton, clip, options).status().code(), ErrorCode::kInvalidArgument);
  options = {};
  options.joints = {99};
  EXPECT_EQ(MultiresFilter(skeleton, clip, options).status().code(), ErrorCode::kInvalidArgument);
  options = {};
  options.gains.band_gains.assign(12, 1.0);  // 121 frames have 6 levels
  EXPECT_TRUE(MultiresFilter(skeleton, clip, options).ok());
  options.gains.band_gains[9] = 2.0;
  EXPECT_EQ(MultiresFilter(skeleton, clip, options).status().code(), ErrorCode::kInvalidArgument);
}

TEST(MultiresFilter, UnitGainsReproduceTheClip) {
  const Skeleton skeleton = testing::WalkerSkeleton();
  testing::WalkerParams p;
  p.duration_s = 9.0;  // a turning walk: heading goes far past the 150-degree tangent range
  const MotionClip clip = testing::WalkerClip(skeleton, p);
  MultiresFilterOptions options;
  options.gains.band_gains = {1, 1, 1, 1, 1, 1};
  Result<MotionClip> out = MultiresFilter(skeleton, clip, options);
  ASSERT_TRUE(out.ok()) << out.status().message();
  EXPECT_LT(testing::MaxRotationError(clip, *out), 1e-9);
  EXPECT_LT(testing::MaxTranslationError(clip, *out), 1e-9);
  EXPECT_EQ(out->keys[3].rotation_frames, clip.keys[3].rotation_frames);
}

TEST(MultiresFilter, GainsActOnlyOnTheSelectedJointsAndBands) {
  const Skeleton skeleton = testing::WalkerSkeleton();
  const MotionClip clip = testing::WalkerClip(skeleton, {});
  MultiresFilterOptions options;
  options.joints = {4};  // Leg_L only
  options.gains.band_gains = {1, 1, 1, 2.0};  // L3 holds the 1 Hz swing at 30 Hz
  Result<MotionClip> out = MultiresFilter(skeleton, clip, options);
  ASSERT_TRUE(out.ok());
  double leg_change = 0.0, other_change = 0.0;
  for (int f = 0; f < clip.num_frames; ++f)
    for (int j = 0; j < clip.num_joints; ++j) {
      const double d = GeodesicAngle(clip.rotation(f, j), out->rotation(f, j));
      (j == 4 ? leg_change : other_change) = std::max(j == 4 ? leg_change : other_change, d);
    }
  // Doubling the stride band of a 0.5 rad, 1 Hz swing adds tenths of a radian.
  EXPECT_GT(leg_change, 0.15);
  EXPECT_LT(other_change, 1e-12);
  EXPECT_LT(testing::MaxTranslationError(clip, *out), 1e-12);
}

TEST(MultiresFilter, RootFeaturesAreFilteredAndReintegrated) {
  const Skeleton skeleton = testing::WalkerSkeleton();
  const MotionClip clip = testing::WalkerClip(skeleton, {});
  MultiresFilterOptions options;
  options.joints = {1};
  options.gains.residual_gain = 0.5;  // halves the average speed, height and yaw rate
  Result<MotionClip> out = MultiresFilter(skeleton, clip, options);
  ASSERT_TRUE(out.ok());
  // The walker's speed, yaw rate and height are constant or oscillate about a constant: the
  // residual holds their averages, so the planar path length, the heading change and the mean
  // height all halve.
  auto path_length = [](const MotionClip& c) {
    double length = 0.0;
    for (int f = 0; f + 1 < c.num_frames; ++f) {
      Eigen::Vector3d step = c.translation(f + 1, 1) - c.translation(f, 1);
      step.y() = 0.0;
      length += step.norm();
    }
    return length;
  };
  EXPECT_NEAR(path_length(*out), 0.5 * path_length(clip), 1e-9);
  double heading_out = 0.0;
  Eigen::Quaterniond tilt;
  SplitHeading(out->rotation(out->num_frames - 1, 1), heading_out, tilt);
  const testing::WalkerParams p;
  EXPECT_NEAR(heading_out, 0.5 * p.yaw_rate_radps * p.duration_s, 1e-9);  // 1.8 rad instead of 3.6
  // Same start on the ground plane.
  EXPECT_LT(std::abs(out->translation(0, 1).x() - clip.translation(0, 1).x()), 1e-12);
  EXPECT_LT(std::abs(out->translation(0, 1).z() - clip.translation(0, 1).z()), 1e-12);
}

}  // namespace
}  // namespace mocapfill
