#include "processing/analysis/correlation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace mocapfill {
namespace {

TEST(Correlation, RejectsBadSegments) {
  Eigen::MatrixXf x = Eigen::MatrixXf::Random(50, 2);
  const FrameSegment outside[] = {{40, 20}};
  EXPECT_EQ(ComputeCorrelationTable(x, outside, 3).status().code(), ErrorCode::kInvalidArgument);
  const FrameSegment overlap[] = {{0, 30}, {20, 10}};
  EXPECT_FALSE(ComputeCorrelationTable(x, overlap, 3).ok());
  const FrameSegment ok[] = {{0, 50}};
  EXPECT_FALSE(ComputeCorrelationTable(x, ok, -1).ok());
}

TEST(Correlation, FindsSignAndLagOfShiftedChannels) {
  const int n = 400;
  std::mt19937 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  // Channel 0: a 1 Hz wave with noise; 1: channel 0 three frames later; 2: its negation;
  // 3: independent noise; 4: constant.
  Eigen::VectorXd base(n + 3);
  for (int i = 0; i < n + 3; ++i) base[i] = std::sin(2.0 * M_PI * i / 30.0) + 0.2 * noise(rng);
  Eigen::MatrixXf x(n, 5);
  for (int i = 0; i < n; ++i) {
    x(i, 0) = static_cast<float>(base[i + 3]);
    x(i, 1) = static_cast<float>(base[i]);  // x1[t + 3] = x0[t]
    x(i, 2) = static_cast<float>(-base[i + 3]);
    x(i, 3) = static_cast<float>(noise(rng));
    x(i, 4) = 2.0f;
  }
  const FrameSegment all[] = {{0, n}};
  for (int threads : {1, 2, 3}) {
    Result<CorrelationTable> table = ComputeCorrelationTable(x, all, 7, threads);
    ASSERT_TRUE(table.ok());
    EXPECT_NEAR(table->at(0, 0).value, 1.0f, 1e-5);
    EXPECT_EQ(table->at(0, 1).lag_frames, 3);
    EXPECT_GT(table->at(0, 1).value, 0.99f);
    EXPECT_EQ(table->at(1, 0).lag_frames, -3);
    EXPECT_NEAR(table->at(0, 2).value, -1.0f, 1e-5);
    EXPECT_EQ(table->at(0, 2).lag_frames, 0);
    EXPECT_LT(table->at(0, 3).max_abs, 0.2f);
    EXPECT_EQ(table->at(0, 4).max_abs, 0.0f);
  }
}

TEST(Correlation, LaggedPairsNeverCrossSegments) {
  // Channel 0 moves only in the last 3 frames of segment 0, channel 1 repeats those values in
  // the first 3 frames of segment 1: they match at lag 3 only across the boundary.
  const int n = 60;
  Eigen::MatrixXf x = Eigen::MatrixXf::Zero(2 * n, 2);
  const float values[] = {1.0f, -2.0f, 3.0f};
  for (int i = 0; i < 3; ++i) {
    x(n - 3 + i, 0) = values[i];
    x(n + i, 1) = values[i];
  }
  const FrameSegment joined[] = {{0, 2 * n}};
  Result<CorrelationTable> across = ComputeCorrelationTable(x, joined, 5);
  ASSERT_TRUE(across.ok());
  EXPECT_EQ(across->at(0, 1).lag_frames, 3);
  EXPECT_GT(across->at(0, 1).max_abs, 0.9f);
  const FrameSegment separate[] = {{0, n}, {n, n}};
  Result<CorrelationTable> within = ComputeCorrelationTable(x, separate, 5);
  ASSERT_TRUE(within.ok());
  EXPECT_LT(within->at(0, 1).max_abs, 0.1f);
}

}  // namespace
}  // namespace mocapfill
