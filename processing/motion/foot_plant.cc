#include "processing/motion/foot_plant.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "processing/core/kinematics.h"
#include "processing/motion/key_fidelity.h"

namespace mocapfill {

namespace {

using Eigen::Vector3d;

double Horizontal(const Vector3d& v) { return std::hypot(v.x(), v.z()); }

}  // namespace

std::vector<double> JointlyKeyedTimes(const MotionClip& clip, const std::vector<int>& joints) {
  std::vector<double> times;
  for (size_t i = 0; i < joints.size(); ++i) {
    const std::vector<double> mine = RotationKeysOf(clip, joints[i]).times_s;
    if (i == 0) {
      times = mine;
      continue;
    }
    std::vector<double> both;
    for (double t : times)
      if (std::any_of(mine.begin(), mine.end(), [t](double m) { return std::abs(m - t) < 1e-6; })) both.push_back(t);
    times = std::move(both);
  }
  std::sort(times.begin(), times.end());
  return times;
}

std::vector<LegForPlanting> LegsToPlant(const RigMapping& mapping, const MotionClip& sketch, int hips) {
  using B = HumanoidBone;
  std::vector<LegForPlanting> legs;
  for (const auto& [side, bones] : {std::pair{"left", std::array{B::kLeftUpperLeg, B::kLeftLowerLeg, B::kLeftFoot}},
                                    std::pair{"right", std::array{B::kRightUpperLeg, B::kRightLowerLeg, B::kRightFoot}}}) {
    if (!mapping.has(bones[0]) || !mapping.has(bones[1]) || !mapping.has(bones[2])) continue;
    LegForPlanting leg{side, {mapping.joint(bones[0]), mapping.joint(bones[1]), mapping.joint(bones[2])}, {}};
    leg.key_times_s = JointlyKeyedTimes(sketch, {hips, leg.chain.upper, leg.chain.lower, leg.chain.end});
    legs.push_back(std::move(leg));
  }
  return legs;
}

FootPlantReport PlantFeet(const Skeleton& skeleton, const std::vector<LegForPlanting>& legs,
                          const FootPlantOptions& options, MotionClip& clip) {
  FootPlantReport report;
  WorldPose pose;
  for (const LegForPlanting& leg : legs) {
    if (leg.key_times_s.size() < 2) continue;
    // The foot where the keys put it.
    std::vector<int> frames;
    std::vector<Vector3d> at_key;
    for (double t : leg.key_times_s) {
      frames.push_back(NearestFrame(clip, t));
      ComputeWorldPose(skeleton, clip, frames.back(), pose);
      at_key.push_back(pose.positions[leg.chain.end]);
    }
    const Eigen::Vector3d hinge = HingeOf(skeleton, clip, leg.chain);
    double lowest = at_key.front().y();
    for (const Vector3d& p : at_key) lowest = std::min(lowest, p.y());
    for (size_t k = 0; k + 1 < at_key.size(); ++k) {
      const Vector3d &from = at_key[k], &to = at_key[k + 1];
      const bool standing = from.y() <= lowest + options.max_height_m && to.y() <= lowest + options.max_height_m &&
                            Horizontal(to - from) <= options.max_slide_m;
      if (!standing || frames[k + 1] - frames[k] < 2) continue;
      FootContact contact{leg.side, leg.key_times_s[k], leg.key_times_s[k + 1], 0.0};
      const double span = clip.time_s(frames[k + 1]) - clip.time_s(frames[k]);
      for (int f = frames[k] + 1; f < frames[k + 1]; ++f) {
        const Vector3d target = from + (clip.time_s(f) - clip.time_s(frames[k])) / span * (to - from);
        ComputeWorldPose(skeleton, clip, f, pose);
        // Large corrections are kept: on the captured clips a foot keyed standing at both ends
        // stands between them (holding only corrections under 5 cm scored worse).
        contact.max_correction_m = std::max(contact.max_correction_m, (pose.positions[leg.chain.end] - target).norm());
        const TwoBoneSolution s = SolveTwoBoneIk(skeleton, pose, leg.chain, target, hinge);
        clip.rotation(f, leg.chain.upper) = s.upper;
        clip.rotation(f, leg.chain.lower) = s.lower;
        clip.rotation(f, leg.chain.end) = s.end;
        ++report.frames_held;
      }
      report.max_correction_m = std::max(report.max_correction_m, contact.max_correction_m);
      report.contacts.push_back(contact);
    }
  }
  return report;
}

}  // namespace mocapfill
