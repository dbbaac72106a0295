#include "processing/motion/resample.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "processing/core/rotation.h"

namespace mocapfill {

namespace {

// Uniform Catmull-Rom between p1 and p2 at parameter u in [0, 1]. Missing neighbours at the
// clip ends are extrapolated linearly, so the end tangent is the secant and not half of it.
Eigen::Vector3d CatmullRom(const Eigen::Vector3d& p0, const Eigen::Vector3d& p1, const Eigen::Vector3d& p2,
                           const Eigen::Vector3d& p3, double u) {
  const double u2 = u * u, u3 = u2 * u;
  return 0.5 * ((2.0 * p1) + (-p0 + p2) * u + (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3) * u2 +
                (-p0 + 3.0 * p1 - 3.0 * p2 + p3) * u3);
}

std::vector<int> MapKeys(const std::vector<int>& frames, double ratio, int out_frames) {
  std::vector<int> out;
  out.reserve(frames.size());
  for (int f : frames) {
    // Ties go to the earlier frame: ceil(x - 0.5).
    const int mapped = static_cast<int>(std::ceil(f * ratio - 0.5 - 1e-9));
    out.push_back(std::clamp(mapped, 0, out_frames - 1));
  }
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// Nearest output frame of each source key frame, at the source frame's explicit time.
std::vector<int> MapKeysByTime(const MotionClip& clip, const std::vector<int>& frames, double rate_hz, int out_frames) {
  std::vector<int> out;
  out.reserve(frames.size());
  for (int f : frames) {
    const int mapped = static_cast<int>(std::ceil(clip.time_s(f) * rate_hz - 0.5 - 1e-9));
    out.push_back(std::clamp(mapped, 0, out_frames - 1));
  }
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// A clip with explicit frame times sampled at f / rate_hz: slerp between the frames around
// each time; translations linear, or cubic Hermite with finite-difference tangents per
// second (Catmull-Rom on non-uniform spacing; secants at the ends).
MotionClip ResampleNonUniform(const MotionClip& clip, const ResampleOptions& options) {
  const int out_frames = ResampledFrameCount(clip, options.rate_hz);
  const int joints = clip.num_joints;
  const std::vector<double>& t = clip.frame_times_s;
  MotionClip out = clip;
  out.frame_times_s.clear();
  out.sample_rate_hz = options.rate_hz;
  out.num_frames = out_frames;
  out.rotations.assign(static_cast<size_t>(out_frames) * joints, Eigen::Quaterniond::Identity());
  out.translations.assign(out.rotations.size(), Eigen::Vector3d::Zero());
  const int last = clip.num_frames - 1;
  const auto tangent = [&](int i, int j) -> Eigen::Vector3d {
    const int a = std::max(i - 1, 0), b = std::min(i + 1, last);
    if (a == b) return Eigen::Vector3d::Zero();
    return (clip.translation(b, j) - clip.translation(a, j)) / (t[b] - t[a]);
  };
  int i = 0;
  for (int f = 0; f < out_frames; ++f) {
    const double time = std::min(f / options.rate_hz, t[last]);
    while (i + 1 < last && t[i + 1] <= time) ++i;
    const int i1 = std::min(i + 1, last);
    const double span = t[i1] - t[i];
    const double u = span > 0.0 ? std::clamp((time - t[i]) / span, 0.0, 1.0) : 0.0;
    for (int j = 0; j < joints; ++j) {
      out.rotation(f, j) = clip.rotation(i, j).slerp(u, clip.rotation(i1, j)).normalized();
      if (!clip.translation_animated[j]) {
        out.translation(f, j) = clip.translation(0, j);
      } else if (options.translation == TranslationInterpolation::kLinear || span <= 0.0) {
        out.translation(f, j) = (1.0 - u) * clip.translation(i, j) + u * clip.translation(i1, j);
      } else {
        const double u2 = u * u, u3 = u2 * u;
        out.translation(f, j) = (2 * u3 - 3 * u2 + 1) * clip.translation(i, j) + (u3 - 2 * u2 + u) * span * tangent(i, j) +
                                (-2 * u3 + 3 * u2) * clip.translation(i1, j) + (u3 - u2) * span * tangent(i1, j);
      }
    }
  }
  out.MakeContinuous();
  for (int j = 0; j < joints && j < static_cast<int>(clip.keys.size()); ++j) {
    out.keys[j].rotation_frames = MapKeysByTime(clip, clip.keys[j].rotation_frames, options.rate_hz, out_frames);
    out.keys[j].translation_frames = MapKeysByTime(clip, clip.keys[j].translation_frames, options.rate_hz, out_frames);
  }
  return out;
}

}  // namespace

Status ResampleOptions::Validate() const {
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0)
    return InvalidArgument("resample: rate_hz must be finite and > 0, got " + std::to_string(rate_hz));
  return OkStatus();
}

int ResampledFrameCount(const MotionClip& clip, double rate_hz) {
  if (clip.num_frames <= 0) return 0;
  return static_cast<int>(std::floor(clip.duration_s() * rate_hz + 1e-6)) + 1;
}

Result<MotionClip> ResampleClip(const MotionClip& clip, const ResampleOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  if (clip.num_frames <= 0) return InvalidData("resample: clip '" + clip.name + "' has no frames");
  if (!std::isfinite(clip.sample_rate_hz) || clip.sample_rate_hz <= 0.0)
    return InvalidData("resample: clip '" + clip.name + "' has an invalid sample rate");
  if (!clip.uniform()) {
    if (clip.frame_times_s.size() != static_cast<size_t>(clip.num_frames))
      return InvalidData("resample: clip '" + clip.name + "' has " + std::to_string(clip.frame_times_s.size()) +
                         " frame times for " + std::to_string(clip.num_frames) + " frames");
    return ResampleNonUniform(clip, options);
  }
  if (std::abs(clip.sample_rate_hz - options.rate_hz) <= 1e-9 * options.rate_hz) return clip;

  const int out_frames = ResampledFrameCount(clip, options.rate_hz);
  const int joints = clip.num_joints;
  MotionClip out = clip;
  out.sample_rate_hz = options.rate_hz;
  out.num_frames = out_frames;
  out.rotations.assign(static_cast<size_t>(out_frames) * joints, Eigen::Quaterniond::Identity());
  out.translations.assign(out.rotations.size(), Eigen::Vector3d::Zero());
  const double step = clip.sample_rate_hz / options.rate_hz;  // source frames per output frame
  const int last = clip.num_frames - 1;
  for (int f = 0; f < out_frames; ++f) {
    const double s = std::min(f * step, static_cast<double>(last));
    const int i = std::min(static_cast<int>(std::floor(s)), std::max(last - 1, 0));
    const int i1 = std::min(i + 1, last);
    const double u = s - i;
    for (int j = 0; j < joints; ++j) {
      out.rotation(f, j) = clip.rotation(i, j).slerp(u, clip.rotation(i1, j)).normalized();
      if (!clip.translation_animated[j]) {
        out.translation(f, j) = clip.translation(0, j);
      } else if (options.translation == TranslationInterpolation::kLinear) {
        out.translation(f, j) = (1.0 - u) * clip.translation(i, j) + u * clip.translation(i1, j);
      } else {
        const Eigen::Vector3d& p1 = clip.translation(i, j);
        const Eigen::Vector3d& p2 = clip.translation(i1, j);
        const Eigen::Vector3d p0 = i > 0 ? clip.translation(i - 1, j) : Eigen::Vector3d(2.0 * p1 - p2);
        const Eigen::Vector3d p3 = i1 < last ? clip.translation(i1 + 1, j) : Eigen::Vector3d(2.0 * p2 - p1);
        out.translation(f, j) = CatmullRom(p0, p1, p2, p3, u);
      }
    }
  }
  out.MakeContinuous();
  const double ratio = options.rate_hz / clip.sample_rate_hz;
  for (int j = 0; j < joints && j < static_cast<int>(clip.keys.size()); ++j) {
    out.keys[j].rotation_frames = MapKeys(clip.keys[j].rotation_frames, ratio, out_frames);
    out.keys[j].translation_frames = MapKeys(clip.keys[j].translation_frames, ratio, out_frames);
  }
  return out;
}

}  // namespace mocapfill
