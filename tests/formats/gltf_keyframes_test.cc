// The resampling core of the glTF reader on its own: rate detection and frame counts.
#include <gtest/gtest.h>

#include "formats/gltf/gltf_keyframes.h"

namespace mocapfill::gltf_internal {
namespace {

std::vector<double> FloatTimes(std::initializer_list<double> seconds) {
  std::vector<double> out;
  for (double s : seconds) out.push_back(static_cast<float>(s));  // as stored in a glTF
  return out;
}

TEST(GltfKeyframes, DetectsTheLowestFittingRate) {
  EXPECT_EQ(DetectFrameRate(FloatTimes({0, 8 / 30.0, 16 / 30.0})), 30.0);
  EXPECT_EQ(DetectFrameRate(FloatTimes({0, 0.5, 1.0})), 24.0);
  EXPECT_EQ(DetectFrameRate(FloatTimes({0, 0.04, 0.4})), 25.0);
  EXPECT_EQ(DetectFrameRate(FloatTimes({0, 1 / 120.0, 2751 / 120.0})), 120.0);
  EXPECT_EQ(DetectFrameRate(FloatTimes({0, 1 / 240.0})), 240.0);
  EXPECT_EQ(DetectFrameRate(FloatTimes({0, 0.0123})), std::nullopt);
}

TEST(GltfKeyframes, FrameCountReachesTheLastKey) {
  EXPECT_EQ(FrameCount(0.0, 30), 1);
  EXPECT_EQ(FrameCount(static_cast<float>(16 / 30.0), 30), 17);
  EXPECT_EQ(FrameCount(1.01, 30), 32);  // the last key lies past frame 30: frame 31 holds it
  EXPECT_EQ(FrameCount(1e300, 240), int64_t{1'000'000'000'000'000} + 1);  // clamped, refused later
}

TEST(GltfKeyframes, KeyedFramesRoundToTheGrid) {
  KeyTrack track;
  track.times_s = FloatTimes({0, 0.26, 16 / 30.0});
  track.components = 3;
  track.values.assign(9, 0.0);
  EXPECT_EQ(KeyedFrames(track, 30, 17), (std::vector<int>{0, 8, 16}));
}

TEST(GltfKeyframes, LinearBetweenOffGridKeys) {
  KeyTrack track;
  track.times_s = {0.0, 0.05};  // 1.5 frames at 30 Hz
  track.components = 3;
  track.values = {0, 0, 0, 3, 6, 9};
  const auto samples = SampleVector3(track, 30, 3);
  EXPECT_NEAR(samples[1].x(), 2.0, 1e-12);
  EXPECT_EQ(samples[2], Eigen::Vector3d(3, 6, 9));  // held after the last key
}

}  // namespace
}  // namespace mocapfill::gltf_internal
