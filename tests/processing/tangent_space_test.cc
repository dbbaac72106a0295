#include "processing/motion/tangent_space.h"

#include <gtest/gtest.h>

#include "processing/core/kinematics.h"
#include "tests/processing/synthetic_motion.h"

namespace mocapfill {
namespace {

using testing::WalkerClip;
using testing::WalkerParams;
using testing::WalkerSkeleton;

constexpr double kRoundTripRad = 1e-9;
constexpr double kRoundTripM = 1e-9;

TEST(TangentSpace, MeanRotationIsSignInvariantAndSymmetric) {
  const Eigen::Quaterniond a(Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitZ()));
  const Eigen::Quaterniond b(Eigen::AngleAxisd(-0.4, Eigen::Vector3d::UnitZ()));
  Eigen::Quaterniond b_flipped = b;
  b_flipped.coeffs() *= -1.0;
  const Eigen::Quaterniond base(Eigen::AngleAxisd(1.0, Eigen::Vector3d(1, 2, 3).normalized()));
  const std::vector<Eigen::Quaterniond> rotations = {base * a, base * b_flipped};
  EXPECT_LT(GeodesicAngle(MeanRotation(rotations), base), 1e-12);
  EXPECT_LT(GeodesicAngle(MeanRotation({}), Eigen::Quaterniond::Identity()), 1e-15);
}

TEST(TangentSpace, SplitHeadingSeparatesYawFromTilt) {
  const Eigen::Quaterniond tilt_in(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitX()));
  for (double yaw : {0.0, 1.0, -2.5, 3.1}) {
    double heading = 0.0;
    Eigen::Quaterniond tilt;
    SplitHeading(YawRotation(yaw) * tilt_in, heading, tilt);
    EXPECT_NEAR(heading, yaw, 1e-12);
    EXPECT_LT(GeodesicAngle(tilt, tilt_in), 1e-12);
    EXPECT_NEAR(tilt.y(), 0.0, 1e-12);
  }
}

TEST(TangentSpace, MotionRootIsTheFirstTranslatingJoint) {
  const Skeleton skeleton = WalkerSkeleton();
  const MotionClip clip = WalkerClip(skeleton, {});
  const MotionClip* clips[] = {&clip};
  EXPECT_EQ(FindMotionRoot(skeleton, clips), 1);  // "Hips", not the static "Root"
  // Still the pelvis when the joint above it translates too (as in some Bandai-Namco clips).
  MotionClip both = clip;
  both.translation_animated[0] = 1;
  const MotionClip* both_clips[] = {&clip, &both};
  EXPECT_EQ(FindMotionRoot(skeleton, both_clips), 1);
  // A translating joint below the pelvis wins over it (the pelvis does not carry it).
  MotionClip leg = clip;
  leg.translation_animated[4] = 1;
  const MotionClip* leg_clips[] = {&leg};
  EXPECT_EQ(FindMotionRoot(skeleton, leg_clips), 1);
  leg.translation_animated[1] = 0;
  EXPECT_EQ(FindMotionRoot(skeleton, leg_clips), 4);
}

TEST(TangentSpace, RootFeaturesOfAKnownPath) {
  const Skeleton skeleton = WalkerSkeleton();
  WalkerParams params;
  params.duration_s = 10.0;  // 9 rad of heading: more than a full turn
  const MotionClip clip = WalkerClip(skeleton, params);
  const RootTrajectory trajectory = ExtractRootTrajectory(skeleton, clip, 1);
  // Heading is unwrapped: it keeps growing past pi.
  EXPECT_NEAR(trajectory.heading_rad.back(), params.yaw_rate_radps * params.duration_s, 1e-9);
  const Eigen::MatrixXd features = RootFeaturesFromTrajectory(trajectory, params.rate_hz);
  ASSERT_EQ(features.rows(), clip.num_frames);
  // Forward differences of a circle: chord length / dt, rotated by half a step.
  const double dpsi = params.yaw_rate_radps / params.rate_hz;
  const double chord = 2.0 * params.speed_mps / params.yaw_rate_radps * std::sin(0.5 * dpsi) * params.rate_hz;
  for (int t = 0; t < clip.num_frames; ++t) {
    EXPECT_NEAR(features(t, kRootYawRate), params.yaw_rate_radps, 1e-9);
    EXPECT_NEAR(features(t, kRootForward), chord * std::cos(0.5 * dpsi), 1e-9);
    EXPECT_NEAR(features(t, kRootLateral), chord * std::sin(0.5 * dpsi), 1e-9);
    EXPECT_NEAR(features(t, kRootHeight), trajectory.position_m[t].y(), 1e-15);
  }
  const RootTrajectory integrated =
      IntegrateRootFeatures(features, params.rate_hz, trajectory.heading_rad[0], trajectory.position_m[0]);
  for (int t = 0; t < clip.num_frames; ++t) {
    EXPECT_LT((integrated.position_m[t] - trajectory.position_m[t]).norm(), kRoundTripM);
    EXPECT_NEAR(integrated.heading_rad[t], trajectory.heading_rad[t], kRoundTripRad);
  }
}

TEST(TangentSpace, DecomposeComposeRoundTripIsExact) {
  const Skeleton skeleton = WalkerSkeleton();
  WalkerParams params;
  params.duration_s = 9.0;
  const MotionClip clip = WalkerClip(skeleton, params);
  const MotionClip* clips[] = {&clip};
  const TangentReference reference = ComputeTangentReference(skeleton, clips, FindMotionRoot(skeleton, clips));
  ASSERT_EQ(reference.root_joint, 1);
  const ClipSignals signals = DecomposeClip(skeleton, clip, reference);
  EXPECT_EQ(signals.tangent.rows(), clip.num_frames);
  EXPECT_EQ(signals.tangent.cols(), 3 * skeleton.num_joints());
  // The root's tangent holds only the small tilt, never the (unbounded) heading.
  EXPECT_LT(signals.tangent.middleCols<3>(3).cwiseAbs().maxCoeff(), 0.06);
  // The right leg's swing is the mirror of the left's about the same mean.
  EXPECT_NEAR(signals.tangent.col(TangentColumn(4, 0)).maxCoeff(), 0.5, 5e-3);
  Result<MotionClip> back = ComposeClip(skeleton, signals, reference, clip);
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_LT(testing::MaxRotationError(clip, *back), kRoundTripRad);
  EXPECT_LT(testing::MaxTranslationError(clip, *back), kRoundTripM);
}

TEST(TangentSpace, ComposeRejectsMismatchedSignals) {
  const Skeleton skeleton = WalkerSkeleton();
  const MotionClip clip = WalkerClip(skeleton, {});
  const MotionClip* clips[] = {&clip};
  const TangentReference reference = ComputeTangentReference(skeleton, clips, 1);
  ClipSignals signals = DecomposeClip(skeleton, clip, reference);
  ClipSignals short_signals = signals;
  short_signals.tangent.conservativeResize(10, Eigen::NoChange);
  EXPECT_EQ(ComposeClip(skeleton, short_signals, reference, clip).status().code(), ErrorCode::kInvalidArgument);
  signals.root_features(5, kRootForward) = NAN;
  EXPECT_EQ(ComposeClip(skeleton, signals, reference, clip).status().code(), ErrorCode::kNumericalFailure);
}

}  // namespace
}  // namespace mocapfill
