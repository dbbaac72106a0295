#include "processing/analysis/phases.h"

#include <gtest/gtest.h>

#include <cmath>

namespace mocapfill {
namespace {

TEST(Phases, ValidateRejectsBadInput) {
  PhaseOptions options;
  options.min_length_s = -1.0;
  EXPECT_EQ(options.Validate().code(), ErrorCode::kInvalidArgument);
  Eigen::VectorXd x = Eigen::VectorXd::Zero(5);
  x[2] = NAN;
  EXPECT_FALSE(FindPhases(x, 30.0).ok());
  EXPECT_FALSE(FindPhases(Eigen::VectorXd::Zero(5), 0.0).ok());
  EXPECT_TRUE(FindPhases(Eigen::VectorXd::Zero(1), 30.0)->empty());
}

TEST(Phases, ASineIsCutAtItsExtrema) {
  // 1 Hz at 30 Hz for 3 s: extrema at t = 0.25 + 0.5 n s, i.e. frames 7.5, 22.5, ...
  // sampled with a quarter-frame offset so each extremum falls on one frame.
  Eigen::VectorXd x(91);
  for (int i = 0; i < 91; ++i) x[i] = std::sin(2.0 * M_PI * (i + 0.5) / 30.0);
  Result<std::vector<Phase>> phases = FindPhases(x, 30.0);
  ASSERT_TRUE(phases.ok());
  ASSERT_EQ(phases->size(), 7u);
  EXPECT_EQ((*phases)[0].first, 0);
  EXPECT_EQ((*phases)[0].last, 7);
  EXPECT_TRUE((*phases)[0].rising);
  for (size_t i = 1; i < phases->size(); ++i) {
    EXPECT_EQ((*phases)[i].first, (*phases)[i - 1].last);
    EXPECT_NE((*phases)[i].rising, (*phases)[i - 1].rising);
  }
  EXPECT_EQ((*phases)[1].last, 22);
  EXPECT_EQ(phases->back().last, 90);
}

TEST(Phases, ShortBlipsAreMergedAndFlatStretchesDoNotCut) {
  Eigen::VectorXd x(60);
  for (int i = 0; i < 60; ++i) x[i] = i < 30 ? i : 60 - i;  // up then down
  x[10] = 9.5;  // a one-frame dip on the way up: two 1-frame phases
  for (int i = 40; i < 45; ++i) x[i] = x[40];  // a flat stretch on the way down
  Result<std::vector<Phase>> phases = FindPhases(x, 30.0);
  ASSERT_TRUE(phases.ok());
  ASSERT_EQ(phases->size(), 2u);
  EXPECT_TRUE((*phases)[0].rising);
  EXPECT_EQ((*phases)[0].last, 30);
  EXPECT_FALSE((*phases)[1].rising);
}

}  // namespace
}  // namespace mocapfill
