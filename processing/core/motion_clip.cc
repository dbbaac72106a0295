#include "processing/core/motion_clip.h"

#include <cmath>

#include "processing/core/rotation.h"

namespace mocapfill {

MotionClip MotionClip::RestPose(const Skeleton& skeleton, int frames, double rate_hz) {
  MotionClip clip;
  clip.sample_rate_hz = rate_hz;
  clip.num_frames = frames;
  clip.num_joints = skeleton.num_joints();
  clip.rotations.resize(static_cast<size_t>(frames) * clip.num_joints);
  clip.translations.resize(clip.rotations.size());
  for (int f = 0; f < frames; ++f) {
    for (int j = 0; j < clip.num_joints; ++j) {
      clip.rotation(f, j) = skeleton.joint(j).rest_rotation;
      clip.translation(f, j) = skeleton.joint(j).rest_translation;
    }
  }
  clip.translation_animated.assign(clip.num_joints, 0);
  clip.keys.assign(clip.num_joints, JointKeys{});
  return clip;
}

void MotionClip::KeyAllFrames() {
  keys.assign(num_joints, JointKeys{});
  for (int j = 0; j < num_joints; ++j) {
    keys[j].rotation_frames.resize(num_frames);
    for (int f = 0; f < num_frames; ++f) keys[j].rotation_frames[f] = f;
    if (translation_animated[j]) keys[j].translation_frames = keys[j].rotation_frames;
  }
}

void MotionClip::MakeContinuous() {
  for (int j = 0; j < num_joints; ++j)
    MakeHemisphereContinuous(rotations, j, num_frames, num_joints);
}

void MotionClip::DetectAnimatedTranslations(double tolerance_m) {
  translation_animated.assign(num_joints, 0);
  for (int j = 0; j < num_joints; ++j)
    for (int f = 1; f < num_frames && !translation_animated[j]; ++f)
      if ((translation(f, j) - translation(0, j)).cwiseAbs().maxCoeff() > tolerance_m) translation_animated[j] = 1;
}

Status MotionClip::Validate(const Skeleton& skeleton) const {
  if (num_joints != skeleton.num_joints())
    return InvalidData("clip '" + name + "' has " + std::to_string(num_joints) + " joints, skeleton has " +
                       std::to_string(skeleton.num_joints()));
  if (num_frames <= 0) return InvalidData("clip '" + name + "' has no frames");
  if (!(sample_rate_hz > 0.0) || !std::isfinite(sample_rate_hz))
    return InvalidData("clip '" + name + "' has an invalid sample rate");
  const size_t n = static_cast<size_t>(num_frames) * num_joints;
  if (rotations.size() != n || translations.size() != n || translation_animated.size() != size_t(num_joints) ||
      keys.size() != size_t(num_joints))
    return Internal("clip '" + name + "' has inconsistent array sizes");
  for (size_t i = 0; i < n; ++i) {
    // Fast acceptance, branch-light: x - x is 0 exactly when x is finite, and a squared
    // norm within 1 +- 1.9e-6 puts the norm within 1e-6 of 1. Anything else takes the
    // exact checks below, which decide and word the error.
    const Eigen::Vector3d& t = translations[i];
    const double squared_norm = rotations[i].coeffs().squaredNorm();
    if ((t.x() - t.x()) + (t.y() - t.y()) + (t.z() - t.z()) == 0.0 && std::abs(squared_norm - 1.0) <= 1.9e-6) continue;
    if (!rotations[i].coeffs().allFinite() || !translations[i].allFinite())
      return InvalidData("clip '" + name + "' has a non-finite value at frame " + std::to_string(i / num_joints) +
                         ", joint '" + skeleton.name(static_cast<int>(i % num_joints)) + "'");
    if (std::abs(rotations[i].norm() - 1.0) > 1e-6)
      return Internal("clip '" + name + "' has a non-unit rotation");
  }
  for (int j = 0; j < num_joints; ++j)
    for (const auto* frames : {&keys[j].rotation_frames, &keys[j].translation_frames})
      for (size_t k = 0; k < frames->size(); ++k)
        if ((*frames)[k] < 0 || (*frames)[k] >= num_frames || (k > 0 && (*frames)[k] <= (*frames)[k - 1]))
          return Internal("clip '" + name + "' has unsorted or out-of-range keys");
  if (!frame_times_s.empty()) {
    if (frame_times_s.size() != static_cast<size_t>(num_frames))
      return InvalidData("clip '" + name + "' has " + std::to_string(frame_times_s.size()) + " frame times for " +
                         std::to_string(num_frames) + " frames");
    if (frame_times_s[0] != 0.0) return InvalidData("clip '" + name + "': the first frame time is not 0");
    for (size_t f = 1; f < frame_times_s.size(); ++f)
      if (!std::isfinite(frame_times_s[f]) || !(frame_times_s[f] > frame_times_s[f - 1]))
        return InvalidData("clip '" + name + "': frame times are not finite and strictly increasing at frame " +
                           std::to_string(f));
  }
  const auto times_ok = [](const std::vector<double>& times) {
    for (size_t k = 0; k < times.size(); ++k)
      if (!std::isfinite(times[k]) || times[k] < 0.0 || (k > 0 && !(times[k] > times[k - 1]))) return false;
    return true;
  };
  for (int j = 0; j < num_joints; ++j) {
    const JointKeys& k = keys[j];
    if (k.rotation_times_s.size() != k.rotation_values.size() ||
        k.translation_times_s.size() != k.translation_values.size() || !times_ok(k.rotation_times_s) ||
        !times_ok(k.translation_times_s))
      return Internal("clip '" + name + "' has inconsistent exact keys for joint '" + skeleton.name(j) + "'");
    for (const Eigen::Quaterniond& q : k.rotation_values)
      if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > 1e-6)
        return Internal("clip '" + name + "' has a non-finite or non-unit exact rotation key");
    for (const Eigen::Vector3d& t : k.translation_values)
      if (!t.allFinite()) return Internal("clip '" + name + "' has a non-finite exact translation key");
  }
  return OkStatus();
}

Status RequireUniform(const MotionClip& clip, const std::string& stage) {
  if (clip.uniform()) return OkStatus();
  return InvalidArgument(stage + ": clip '" + clip.name +
                         "' has explicit (non-uniform) frame times; resample it to a frame rate first");
}

}  // namespace mocapfill
