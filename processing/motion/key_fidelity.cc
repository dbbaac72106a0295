#include "processing/motion/key_fidelity.h"

#include <algorithm>
#include <cmath>

namespace mocapfill {

namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;


}  // namespace

FrameBracket FindBracket(const MotionClip& clip, double time_s) {
  const int last = clip.num_frames - 1;
  if (last <= 0 || !(time_s > clip.time_s(0))) return {0, 0, 0.0};
  if (time_s >= clip.time_s(last)) return {last, last, 0.0};
  int lo = 0, hi = last;  // time_s(lo) < time_s < ... <= time_s(hi), narrowed to hi = lo + 1
  if (clip.uniform()) {
    // The grid's own guess, corrected by the comparisons below against rounding.
    lo = std::clamp(static_cast<int>(std::floor(time_s * clip.sample_rate_hz)), 0, last - 1);
    hi = lo + 1;
    while (lo > 0 && clip.time_s(lo) > time_s) --lo, --hi;
    while (hi < last && clip.time_s(hi) <= time_s) ++lo, ++hi;
  } else {
    const auto& t = clip.frame_times_s;
    hi = static_cast<int>(std::upper_bound(t.begin(), t.end(), time_s) - t.begin());
    lo = hi - 1;
  }
  const double t0 = clip.time_s(lo), t1 = clip.time_s(hi);
  return {lo, hi, std::clamp((time_s - t0) / (t1 - t0), 0.0, 1.0)};
}

int NearestFrame(const MotionClip& clip, double time_s) {
  const FrameBracket k = FindBracket(clip, time_s);
  return k.u > 0.5 ? k.b : k.a;
}

RotationKeys RotationKeysOf(const MotionClip& clip, int joint) {
  const JointKeys& k = clip.keys[joint];
  if (k.has_exact_rotations() && k.rotation_times_s.size() == k.rotation_values.size())
    return {k.rotation_times_s, k.rotation_values};
  RotationKeys keys;
  for (int f : k.rotation_frames) {
    keys.times_s.push_back(clip.time_s(f));
    keys.values.push_back(clip.rotation(f, joint));
  }
  return keys;
}

TranslationKeys TranslationKeysOf(const MotionClip& clip, int joint) {
  const JointKeys& k = clip.keys[joint];
  if (k.has_exact_translations() && k.translation_times_s.size() == k.translation_values.size())
    return {k.translation_times_s, k.translation_values};
  TranslationKeys keys;
  for (int f : k.translation_frames) {
    keys.times_s.push_back(clip.time_s(f));
    keys.values.push_back(clip.translation(f, joint));
  }
  return keys;
}

Eigen::Quaterniond SampleRotationAt(const MotionClip& clip, int joint, double time_s) {
  const FrameBracket k = FindBracket(clip, time_s);
  if (k.a == k.b || k.u == 0.0) return clip.rotation(k.a, joint).normalized();
  return clip.rotation(k.a, joint).slerp(k.u, clip.rotation(k.b, joint)).normalized();
}

Eigen::Vector3d SampleTranslationAt(const MotionClip& clip, int joint, double time_s) {
  const FrameBracket k = FindBracket(clip, time_s);
  if (k.a == k.b || k.u == 0.0) return clip.translation(k.a, joint);
  return (1.0 - k.u) * clip.translation(k.a, joint) + k.u * clip.translation(k.b, joint);
}

Result<KeyErrors> MeasureKeyErrors(const Skeleton& written_skeleton, const MotionClip& written,
                                   const Skeleton& sketch_skeleton, const MotionClip& sketch) {
  RETURN_IF_ERROR(written.Validate(written_skeleton).WithContext("written clip"));
  RETURN_IF_ERROR(sketch.Validate(sketch_skeleton).WithContext("sketch"));
  KeyErrors errors;
  double rotation_sum = 0.0, translation_sum = 0.0;
  for (int j = 0; j < sketch.num_joints; ++j) {
    const JointKeys& keys = sketch.keys[j];
    if (keys.empty() && !keys.has_exact_rotations() && !keys.has_exact_translations()) continue;
    const std::string& name = sketch_skeleton.name(j);
    const auto w = written_skeleton.Find(name);
    if (!w) {
      errors.unmatched_joints.push_back(name);
      continue;
    }
    KeyError e;
    e.joint = name;
    const RotationKeys rotation_keys = RotationKeysOf(sketch, j);
    const std::vector<double>& times = rotation_keys.times_s;
    const std::vector<Eigen::Quaterniond>& rotations = rotation_keys.values;
    double sum = 0.0;
    for (size_t k = 0; k < times.size(); ++k) {
      const double deg = SampleRotationAt(written, *w, times[k]).angularDistance(rotations[k].normalized()) *
                         kDegreesPerRadian;
      sum += deg;
      if (deg > e.rotation_max_deg || e.rotation_count == 0) {
        e.rotation_max_deg = deg;
        e.rotation_max_at_s = times[k];
      }
      ++e.rotation_count;
    }
    if (e.rotation_count) e.rotation_mean_deg = sum / e.rotation_count;
    rotation_sum += sum;
    const TranslationKeys translation_keys = TranslationKeysOf(sketch, j);
    const std::vector<Eigen::Vector3d>& translations = translation_keys.values;
    sum = 0.0;
    for (size_t k = 0; k < translations.size(); ++k) {
      const double t = translation_keys.times_s[k];
      const double m = (SampleTranslationAt(written, *w, t) - translations[k]).norm();
      sum += m;
      if (m > e.translation_max_m || e.translation_count == 0) {
        e.translation_max_m = m;
        e.translation_max_at_s = t;
      }
      ++e.translation_count;
    }
    if (e.translation_count) e.translation_mean_m = sum / e.translation_count;
    translation_sum += sum;
    errors.rotation_count += e.rotation_count;
    errors.translation_count += e.translation_count;
    errors.rotation_max_deg = std::max(errors.rotation_max_deg, e.rotation_max_deg);
    errors.translation_max_m = std::max(errors.translation_max_m, e.translation_max_m);
    errors.joints.push_back(std::move(e));
  }
  if (errors.rotation_count) errors.rotation_mean_deg = rotation_sum / errors.rotation_count;
  if (errors.translation_count) errors.translation_mean_m = translation_sum / errors.translation_count;
  return errors;
}

Result<KeyErrors> MeasureKeyErrors(const Skeleton& skeleton, const MotionClip& written, const MotionClip& sketch) {
  return MeasureKeyErrors(skeleton, written, skeleton, sketch);
}

}  // namespace mocapfill
