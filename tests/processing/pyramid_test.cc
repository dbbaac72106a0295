#include "processing/filtering/pyramid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "processing/filtering/window_mean.h"

namespace mocapfill {
namespace {

constexpr double kExact = 1e-12;  // reconstruction of a telescoping sum, in signal units

Eigen::MatrixXd RandomSignal(int rows, int cols, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, 1.0);
  Eigen::MatrixXd x(rows, cols);
  for (int c = 0; c < cols; ++c) {
    double walk = 0.0;  // a random walk has energy in every band, like motion curves
    for (int r = 0; r < rows; ++r) x(r, c) = (walk += noise(rng));
  }
  return x;
}

TEST(Pyramid, OptionsValidateRejectsEveryInvalidValue) {
  PyramidOptions options;
  EXPECT_TRUE(options.Validate().ok());
  options.levels = -1;
  EXPECT_EQ(options.Validate().code(), ErrorCode::kInvalidArgument);
  options.levels = 17;
  EXPECT_FALSE(options.Validate().ok());
  options = {};
  options.min_band_peak_hz = 0.0;
  EXPECT_FALSE(options.Validate().ok());
  EXPECT_FALSE(BuildPyramid(Eigen::MatrixXd(0, 3), 30.0, {}).ok());
  Eigen::MatrixXd nan = Eigen::MatrixXd::Zero(10, 1);
  nan(3, 0) = NAN;
  EXPECT_FALSE(BuildPyramid(nan, 30.0, {}).ok());
}

TEST(Pyramid, BandPeaksMatchTheDesignTable) {
  // Band peaks of the 5-tap a-trous pyramid at 30 Hz: L0 15, L1 4.2, L2 2.0, L3 0.99, L4 0.49,
  // L5 0.25 Hz.
  const double expected[] = {15.0, 4.2, 2.0, 0.99, 0.49, 0.25};
  for (int k = 0; k < 6; ++k) EXPECT_NEAR(BandPeakHz(k, 30.0), expected[k], 0.03 * expected[k]) << "band " << k;
  // The band index shifts by log2(rate ratio): L3 at 30 Hz is L5 at 120 Hz.
  EXPECT_NEAR(BandPeakHz(5, 120.0), BandPeakHz(3, 30.0), 0.01 * BandPeakHz(3, 30.0));
  EXPECT_EQ(BandForFrequency(1.0, 30.0, 7), 3);
  EXPECT_EQ(BandForFrequency(1.0, 120.0, 9), 5);
  EXPECT_EQ(BandsInRange(0.4, 2.5, 30.0, 7), (std::vector<int>{2, 3, 4}));
}

TEST(Pyramid, AutomaticLevelsFollowLog2AndTheLowBandCap) {
  EXPECT_EQ(AutomaticLevels(1, 30.0), 0);
  EXPECT_EQ(AutomaticLevels(2, 30.0), 1);
  EXPECT_EQ(AutomaticLevels(64, 30.0), 6);
  EXPECT_EQ(AutomaticLevels(127, 30.0), 6);
  // 10000 frames would give 13 levels; the 0.1 Hz cap keeps L6 (0.12 Hz) and drops L7.
  EXPECT_EQ(AutomaticLevels(10000, 30.0), 7);
  EXPECT_EQ(AutomaticLevels(10000, 120.0), 9);
}

TEST(Pyramid, ReconstructionIsExactWithUnitGains) {
  const Eigen::MatrixXd x = RandomSignal(211, 5, 1);
  for (PyramidBoundary boundary : {PyramidBoundary::kClamp, PyramidBoundary::kPeriodic}) {
    PyramidOptions options;
    options.boundary = boundary;
    Result<Pyramid> pyramid = BuildPyramid(x, 30.0, options);
    ASSERT_TRUE(pyramid.ok());
    EXPECT_EQ(pyramid->levels(), 7);
    Result<Eigen::MatrixXd> y = Reconstruct(*pyramid, {});
    ASSERT_TRUE(y.ok());
    EXPECT_LT((*y - x).cwiseAbs().maxCoeff(), kExact);
    EXPECT_LT((pyramid->Gaussian(0) - x).cwiseAbs().maxCoeff(), kExact);
  }
}

TEST(Pyramid, ConstantAndLinearSignalsHaveNoBandEnergyAwayFromTheEnds) {
  const int m = 128;
  Eigen::MatrixXd x(m, 2);
  for (int i = 0; i < m; ++i) x(i, 0) = 3.5, x(i, 1) = 0.25 * i;
  Result<Pyramid> pyramid = BuildPyramid(x, 30.0, {});
  ASSERT_TRUE(pyramid.ok());
  for (int k = 0; k < pyramid->levels(); ++k) {
    EXPECT_LT(pyramid->bands[k].col(0).cwiseAbs().maxCoeff(), kExact);
    // The symmetric kernel keeps a line; only samples within 2 * 2^k * ... of the clamped ends differ.
    const int reach = (1 << (k + 2)) - 1;  // level 0..k spread 2*(1+2+...+2^k) samples
    if (2 * reach < m) {
      EXPECT_LT(pyramid->bands[k].col(1).segment(reach, m - 2 * reach).cwiseAbs().maxCoeff(), 1e-9) << "band " << k;
    }
  }
}

TEST(Pyramid, PeriodicBoundaryHasNoEndEffectsOnACyclicSignal) {
  const int m = 120;  // 4 periods of 1 Hz at 30 Hz
  Eigen::MatrixXd x(m, 1);
  for (int i = 0; i < m; ++i) x(i, 0) = std::sin(2.0 * M_PI * i / 30.0);
  PyramidOptions options;
  options.boundary = PyramidBoundary::kPeriodic;
  Result<Pyramid> pyramid = BuildPyramid(x, 30.0, options);
  ASSERT_TRUE(pyramid.ok());
  // A sine stays a sine (scaled) under a periodic linear filter: every band is shift-invariant.
  const Eigen::VectorXd l3 = pyramid->bands[3].col(0);
  const double amplitude = l3.cwiseAbs().maxCoeff();
  EXPECT_GT(amplitude, 0.3);
  for (int i = 0; i + 30 < m; ++i) EXPECT_NEAR(l3[i], l3[i + 30], 1e-12);
}

TEST(Pyramid, GainsScaleABandAndItsEnergyByGainSquared) {
  const Eigen::MatrixXd x = RandomSignal(300, 3, 2);
  Result<Pyramid> pyramid = BuildPyramid(x, 30.0, {});
  ASSERT_TRUE(pyramid.ok());
  BandGains gains;
  gains.band_gains = {1.0, 1.0, 2.5};
  Result<Eigen::MatrixXd> y = Reconstruct(*pyramid, gains);
  ASSERT_TRUE(y.ok());
  // x' - x = (g - 1) L_2, so the change carries (g - 1)^2 of L_2's energy ...
  const double band_energy = pyramid->bands[2].squaredNorm();
  EXPECT_NEAR((*y - x).squaredNorm(), 1.5 * 1.5 * band_energy, 1e-9 * band_energy);
  // ... and the scaled band, g^2.
  const Eigen::MatrixXd scaled = *y - (x - pyramid->bands[2]);
  EXPECT_NEAR(scaled.squaredNorm(), 2.5 * 2.5 * band_energy, 1e-9 * band_energy);
  // Gains for bands the signal does not have: ignored when 1, an error otherwise.
  gains.band_gains.assign(9, 1.0);
  ASSERT_TRUE(Reconstruct(*pyramid, gains).ok());
  EXPECT_LT((*Reconstruct(*pyramid, gains) - x).cwiseAbs().maxCoeff(), kExact);
  gains.band_gains[8] = 1.2;
  EXPECT_EQ(Reconstruct(*pyramid, gains).status().code(), ErrorCode::kInvalidArgument);
}

TEST(Pyramid, FloatSmoothingAgreesWithDouble) {
  const Eigen::MatrixXd x = RandomSignal(100, 2, 3);
  const Eigen::MatrixXf xf = x.cast<float>();
  for (int level = 0; level < 5; ++level) {
    const Eigen::MatrixXd d = SmoothLevel(x, level, PyramidBoundary::kClamp);
    const Eigen::MatrixXf f = SmoothLevel(xf, level, PyramidBoundary::kClamp);
    EXPECT_LT((d - f.cast<double>()).cwiseAbs().maxCoeff(), 1e-4 * x.cwiseAbs().maxCoeff());
  }
}

// Each frame's window holds `half` frames on either side, fewer at the clip's ends.
TEST(WindowMean, AveragesACentredWindowClampedAtTheEnds) {
  Eigen::MatrixXd m(5, 2);
  m << 1, 10, 2, 20, 3, 30, 4, 40, 8, 80;
  const Eigen::MatrixXd mean = WindowMean(m, 1);
  EXPECT_DOUBLE_EQ(mean(0, 0), 1.5);  // frames 0 and 1
  EXPECT_DOUBLE_EQ(mean(2, 0), 3.0);  // frames 1 to 3
  EXPECT_DOUBLE_EQ(mean(4, 1), 60.0);  // frames 3 and 4
  EXPECT_TRUE(WindowMean(m, 0).isApprox(m));
}

}  // namespace
}  // namespace mocapfill
