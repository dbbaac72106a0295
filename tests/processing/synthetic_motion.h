// Clips built in code for the processing tests: a small walker whose motion is known in
// closed form (turning path, bobbing height, swinging legs), so tests can assert exact values.
#pragma once

#include <cmath>
#include <string>

#include "processing/core/motion_clip.h"
#include "processing/core/rotation.h"
#include "processing/core/skeleton.h"

namespace mocapfill::testing {

// Root (static, like Bandai-Namco joint_Root) -> Hips (translating) -> Spine -> Head,
// Hips -> Leg_L, Hips -> Leg_R.
inline Skeleton WalkerSkeleton() {
  std::vector<Joint> joints(6);
  const char* names[] = {"Root", "Hips", "Spine", "Head", "Leg_L", "Leg_R"};
  const int parents[] = {kNoParent, 0, 1, 2, 1, 1};
  const Eigen::Vector3d offsets[] = {{0, 0, 0}, {0, 0.9, 0}, {0, 0.2, 0}, {0, 0.4, 0}, {0.1, -0.05, 0}, {-0.1, -0.05, 0}};
  for (int j = 0; j < 6; ++j) {
    joints[j].name = names[j];
    joints[j].parent = parents[j];
    joints[j].rest_translation = offsets[j];
  }
  return Skeleton::Build(joints).value();
}

struct WalkerParams {
  double rate_hz = 30.0;
  double duration_s = 4.0;
  double speed_mps = 1.2;
  double yaw_rate_radps = 0.9;   // turns more than a full circle in 8 s
  double stride_hz = 1.0;        // leg swing frequency
  double phase_rad = 0.0;
};

// Analytic walker. Heading psi(t) = yaw_rate * t; the hips move forward (heading frame +Z)
// at speed_mps; legs swing anti-phase about X; spine sways at 2.3 Hz; head nods at 0.4 Hz.
inline MotionClip WalkerClip(const Skeleton& skeleton, const WalkerParams& p) {
  const int frames = static_cast<int>(std::lround(p.duration_s * p.rate_hz)) + 1;
  MotionClip clip = MotionClip::RestPose(skeleton, frames, p.rate_hz);
  clip.name = "walker";
  const double w = 2.0 * kPi * p.stride_hz;
  for (int f = 0; f < frames; ++f) {
    const double t = f / p.rate_hz;
    const double psi = p.yaw_rate_radps * t;
    // Closed-form position on the circle travelled at constant speed and yaw rate.
    const double r = p.speed_mps / p.yaw_rate_radps;
    const Eigen::Vector3d position(r * (1.0 - std::cos(psi)), 0.9 + 0.03 * std::sin(2.0 * w * t + p.phase_rad),
                                   r * std::sin(psi));
    clip.translation(f, 1) = position;
    const Eigen::Quaterniond tilt(Eigen::AngleAxisd(0.05 * std::sin(w * t + p.phase_rad), Eigen::Vector3d::UnitX()));
    clip.rotation(f, 1) = Eigen::Quaterniond(Eigen::AngleAxisd(psi, Eigen::Vector3d::UnitY())) * tilt;
    clip.rotation(f, 2) = Eigen::Quaterniond(Eigen::AngleAxisd(0.1 * std::sin(2.0 * kPi * 2.3 * t), Eigen::Vector3d::UnitZ()));
    clip.rotation(f, 3) = Eigen::Quaterniond(Eigen::AngleAxisd(0.2 * std::sin(2.0 * kPi * 0.4 * t), Eigen::Vector3d::UnitX()));
    clip.rotation(f, 4) = Eigen::Quaterniond(Eigen::AngleAxisd(0.5 * std::sin(w * t + p.phase_rad), Eigen::Vector3d::UnitX()));
    clip.rotation(f, 5) = Eigen::Quaterniond(Eigen::AngleAxisd(-0.5 * std::sin(w * t + p.phase_rad), Eigen::Vector3d::UnitX()));
  }
  clip.MakeContinuous();
  clip.DetectAnimatedTranslations();
  clip.KeyAllFrames();
  return clip;
}

// Largest geodesic angle between corresponding rotations and largest translation distance.
inline double MaxRotationError(const MotionClip& a, const MotionClip& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.rotations.size(); ++i) worst = std::max(worst, GeodesicAngle(a.rotations[i], b.rotations[i]));
  return worst;
}
inline double MaxTranslationError(const MotionClip& a, const MotionClip& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.translations.size(); ++i) worst = std::max(worst, (a.translations[i] - b.translations[i]).norm());
  return worst;
}

}  // namespace mocapfill::testing
