#include "processing/motion/resample.h"

#include <gtest/gtest.h>

#include "tests/processing/synthetic_motion.h"

namespace mocapfill {
namespace {

TEST(Resample, ValidateRejectsBadRates) {
  ResampleOptions options;
  options.rate_hz = 0.0;
  EXPECT_EQ(options.Validate().code(), ErrorCode::kInvalidArgument);
  options.rate_hz = NAN;
  EXPECT_FALSE(options.Validate().ok());
  MotionClip empty;
  EXPECT_EQ(ResampleClip(empty, {}).status().code(), ErrorCode::kInvalidData);
}

TEST(Resample, From120HzMatchesTheAnalyticMotion) {
  const Skeleton skeleton = testing::WalkerSkeleton();
  testing::WalkerParams p120;
  p120.rate_hz = 120.0;
  p120.duration_s = 2.0;
  testing::WalkerParams p30 = p120;
  p30.rate_hz = 30.0;
  const MotionClip source = testing::WalkerClip(skeleton, p120);
  const MotionClip expected = testing::WalkerClip(skeleton, p30);
  ASSERT_EQ(ResampledFrameCount(source, 30.0), expected.num_frames);
  for (auto interpolation : {TranslationInterpolation::kLinear, TranslationInterpolation::kCubic}) {
    ResampleOptions options;
    options.translation = interpolation;
    Result<MotionClip> out = ResampleClip(source, options);
    ASSERT_TRUE(out.ok());
    EXPECT_EQ(out->num_frames, expected.num_frames);
    EXPECT_DOUBLE_EQ(out->sample_rate_hz, 30.0);
    // Every 4th source frame is an output frame: exact.
    EXPECT_LT(testing::MaxRotationError(*out, expected), 1e-12);
    EXPECT_LT(testing::MaxTranslationError(*out, expected), 1e-12);
    EXPECT_EQ(out->keys[1].rotation_frames.size(), static_cast<size_t>(out->num_frames));
  }
}

TEST(Resample, UpsamplingInterpolatesBetweenFrames) {
  const Skeleton skeleton = testing::WalkerSkeleton();
  testing::WalkerParams p30;
  p30.duration_s = 2.0;
  testing::WalkerParams p60 = p30;
  p60.rate_hz = 60.0;
  const MotionClip source = testing::WalkerClip(skeleton, p30);
  const MotionClip expected = testing::WalkerClip(skeleton, p60);
  ResampleOptions options;
  options.rate_hz = 60.0;
  Result<MotionClip> cubic = ResampleClip(source, options);
  options.translation = TranslationInterpolation::kLinear;
  Result<MotionClip> linear = ResampleClip(source, options);
  ASSERT_TRUE(cubic.ok() && linear.ok());
  // Slerp of a 1 Hz, 0.5 rad swing sampled at 30 Hz is within 0.3 degrees of the truth.
  EXPECT_LT(testing::MaxRotationError(*cubic, expected), 0.3 * kRadPerDeg);
  // Cubic follows the curved path better than linear.
  EXPECT_LT(testing::MaxTranslationError(*cubic, expected), 0.5 * testing::MaxTranslationError(*linear, expected));
}

TEST(Resample, KeysMapToTheNearestFrame) {
  const Skeleton skeleton = testing::WalkerSkeleton();
  testing::WalkerParams p;
  p.rate_hz = 24.0;
  MotionClip clip = testing::WalkerClip(skeleton, p);
  clip.keys.assign(clip.num_joints, {});
  clip.keys[4].rotation_frames = {0, 5, 6, 7, 48, 96};  // 0, 0.208, 0.25, 0.29, 2, 4 s
  Result<MotionClip> out = ResampleClip(clip, {});
  ASSERT_TRUE(out.ok());
  // At 30 Hz: 0, 6.25 -> 6, 7.5 -> 7 (tie to earlier), 8.75 -> 9, 60, 120.
  EXPECT_EQ(out->keys[4].rotation_frames, (std::vector<int>{0, 6, 7, 9, 60, 120}));
  EXPECT_TRUE(out->keys[2].empty());
}

}  // namespace
}  // namespace mocapfill
