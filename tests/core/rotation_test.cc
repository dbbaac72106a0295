#include "processing/core/rotation.h"

#include <gtest/gtest.h>

#include <random>

namespace mocapfill {
namespace {

constexpr double kAngleToleranceRad = 1e-9;

const char* const kAllOrders[] = {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX"};

TEST(EulerOrder, ParsesEveryTaitBryanOrderAndRejectsOthers) {
  for (const char* text : kAllOrders) {
    const auto order = EulerOrder::Parse(text);
    ASSERT_TRUE(order) << text;
    EXPECT_EQ(order->ToString(), text);
  }
  EXPECT_FALSE(EulerOrder::Parse("XXY"));
  EXPECT_FALSE(EulerOrder::Parse("XY"));
  EXPECT_FALSE(EulerOrder::Parse("ABC"));
  EXPECT_EQ(EulerOrder::Parse("zxy")->ToString(), "ZXY");
}

TEST(Euler, IntrinsicCompositionMatchesAxisProduct) {
  // ZXY with (10, 20, 30) degrees is Rz(10) * Rx(20) * Ry(30).
  const auto q = EulerDegreesToQuaternion({10, 20, 30}, *EulerOrder::Parse("ZXY"));
  const Eigen::Quaterniond expected = Eigen::AngleAxisd(10 * kRadPerDeg, Eigen::Vector3d::UnitZ()) *
                                      Eigen::AngleAxisd(20 * kRadPerDeg, Eigen::Vector3d::UnitX()) *
                                      Eigen::AngleAxisd(30 * kRadPerDeg, Eigen::Vector3d::UnitY());
  EXPECT_LT(GeodesicAngle(q, expected), kAngleToleranceRad);
}

TEST(Euler, RoundTripsEveryOrderOnRandomAngles) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-179.0, 179.0), middle(-89.0, 89.0);
  for (const char* text : kAllOrders) {
    const EulerOrder order = *EulerOrder::Parse(text);
    for (int n = 0; n < 500; ++n) {
      const std::array<double, 3> in{angle(rng), middle(rng), angle(rng)};
      const auto q = EulerDegreesToQuaternion(in, order);
      const auto out = QuaternionToEulerDegrees(q, order);
      for (int i = 0; i < 3; ++i) EXPECT_NEAR(out[i], in[i], 1e-7) << text << " angle " << i;
    }
  }
}

TEST(Euler, GimbalLockStillReproducesTheRotation) {
  for (const char* text : kAllOrders) {
    const EulerOrder order = *EulerOrder::Parse(text);
    const auto q = EulerDegreesToQuaternion({35, 90, -20}, order);
    const auto out = QuaternionToEulerDegrees(q, order);
    EXPECT_LT(GeodesicAngle(EulerDegreesToQuaternion(out, order), q), 1e-7) << text;
  }
}

TEST(Euler, PreviousFrameKeepsAnglesContinuousAcross180) {
  const EulerOrder order = *EulerOrder::Parse("ZYX");
  std::array<double, 3> previous{170, 10, 5};
  for (double z = 170; z < 260; z += 7) {
    const auto q = EulerDegreesToQuaternion({z, 10, 5}, order);
    const auto out = QuaternionToEulerDegrees(q, order, &previous);
    EXPECT_NEAR(out[0], z, 1e-7);  // no jump of 360 degrees
    previous = out;
  }
}

TEST(Quaternion, HemisphereContinuityFlipsSigns) {
  std::vector<Eigen::Quaterniond> track = {Eigen::Quaterniond(1, 0, 0, 0), Eigen::Quaterniond(-0.99, -0.1, 0, 0).normalized()};
  MakeHemisphereContinuous(track, 0, 2, 1);
  EXPECT_GT(track[1].w(), 0.0);
}

TEST(Quaternion, ExpLogRoundTripAndGeodesicAngle) {
  const Eigen::Vector3d v(0.3, -0.2, 0.9);
  EXPECT_LT((LogMap(ExpMap(v)) - v).norm(), 1e-12);
  EXPECT_NEAR(GeodesicAngle(Eigen::Quaterniond::Identity(), ExpMap(v)), v.norm(), 1e-12);
  const Eigen::Quaterniond q = ExpMap(v);
  EXPECT_NEAR(GeodesicAngle(q, Eigen::Quaterniond(-q.coeffs())), 0.0, 1e-12);
}

}  // namespace
}  // namespace mocapfill
