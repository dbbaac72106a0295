#include "processing/motion/key_fidelity.h"

#include <algorithm>
#include <cmath>

namespace mocapfill {

namespace {

constexpr double kDegreesPerRadian = 180.0 / 3.14159265358979323846;

// The frames around `time_s` and the fraction towards the second: (i, i + 1, u) with
// time_s(i) <= time_s < time_s(i + 1); (first, first, 0) or (last, last, 0) outside.
struct Bracket {
  int a = 0;
  int b = 0;
  double u = 0.0;
};

Bracket FindBracket(const MotionClip& clip, double time_s) {
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

struct KeySet {
  std::vector<double> times;
  std::vector<Eigen::Quaterniond> rotations;
  std::vector<Eigen::Vector3d> translations;
};

}  // namespace

Eigen::Quaterniond SampleRotationAt(const MotionClip& clip, int joint, double time_s) {
  const Bracket k = FindBracket(clip, time_s);
  if (k.a == k.b || k.u == 0.0) return clip.rotation(k.a, joint).normalized();
  return clip.rotation(k.a, joint).slerp(k.u, clip.rotation(k.b, joint)).normalized();
}

Eigen::Vector3d SampleTranslationAt(const MotionClip& clip, int joint, double time_s) {
  const Bracket k = FindBracket(clip, time_s);
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
    // Rotation keys: exact when the source had them, else the keyed frames.
    std::vector<double> times = keys.rotation_times_s;
    std::vector<Eigen::Quaterniond> rotations = keys.rotation_values;
    if (!keys.has_exact_rotations()) {
      for (int f : keys.rotation_frames) {
        times.push_back(sketch.time_s(f));
        rotations.push_back(sketch.rotation(f, j));
      }
    }
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
    // Translation keys, likewise.
    times = keys.translation_times_s;
    std::vector<Eigen::Vector3d> translations = keys.translation_values;
    if (!keys.has_exact_translations()) {
      for (int f : keys.translation_frames) {
        times.push_back(sketch.time_s(f));
        translations.push_back(sketch.translation(f, j));
      }
    }
    sum = 0.0;
    for (size_t k = 0; k < times.size(); ++k) {
      const double m = (SampleTranslationAt(written, *w, times[k]) - translations[k]).norm();
      sum += m;
      if (m > e.translation_max_m || e.translation_count == 0) {
        e.translation_max_m = m;
        e.translation_max_at_s = times[k];
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
