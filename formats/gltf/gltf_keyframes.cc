#include "formats/gltf/gltf_keyframes.h"

#include <algorithm>
#include <cmath>

namespace mocapfill::gltf_internal {

namespace {

constexpr double kCandidateRatesHz[] = {24, 25, 30, 48, 50, 60, 100, 120, 240};

// Key positions in frame units; keys within the snap tolerance of a frame sit exactly on
// it, so that STEP holds and keyed values land on their frames despite float32 times.
std::vector<double> KeyPositions(const std::vector<double>& times_s, double rate_hz) {
  std::vector<double> positions(times_s.size());
  for (size_t k = 0; k < times_s.size(); ++k) {
    const double u = times_s[k] * rate_hz;
    const double nearest = std::round(u);
    positions[k] = std::abs(u - nearest) <= kFrameSnapToleranceS * rate_hz ? nearest : u;
  }
  return positions;
}

// Where frame u falls among the keys: key k and fraction s towards key k + 1
// (s = 0 and k = an end key outside the keyed range).
struct Segment {
  size_t k = 0;
  double s = 0.0;
};

class SegmentFinder {
 public:
  explicit SegmentFinder(const std::vector<double>& positions) : positions_(positions) {}
  // Frames are visited in increasing order, so the search only moves forward.
  Segment At(double u) {
    const size_t n = positions_.size();
    if (u <= positions_[0]) return {0, 0.0};
    if (u >= positions_[n - 1]) return {n - 1, 0.0};
    while (k_ + 1 < n && positions_[k_ + 1] <= u) ++k_;
    return {k_, (u - positions_[k_]) / (positions_[k_ + 1] - positions_[k_])};
  }

 private:
  const std::vector<double>& positions_;
  size_t k_ = 0;
};

// Component c of key k's value (the middle element of a CUBICSPLINE triplet).
double Value(const KeyTrack& t, size_t k, int c) {
  const size_t stride = t.interpolation == Interpolation::kCubicSpline ? 3 : 1;
  const size_t offset = t.interpolation == Interpolation::kCubicSpline ? 1 : 0;
  return t.values[(k * stride + offset) * t.components + c];
}
double InTangent(const KeyTrack& t, size_t k, int c) { return t.values[(k * 3) * t.components + c]; }
double OutTangent(const KeyTrack& t, size_t k, int c) { return t.values[(k * 3 + 2) * t.components + c]; }

// Cubic Hermite of the glTF spec; tangents are per second, so they scale with the key spacing.
double Hermite(const KeyTrack& t, size_t k, double s, double spacing_s, int c) {
  const double s2 = s * s, s3 = s2 * s;
  return (2 * s3 - 3 * s2 + 1) * Value(t, k, c) + (s3 - 2 * s2 + s) * spacing_s * OutTangent(t, k, c) +
         (-2 * s3 + 3 * s2) * Value(t, k + 1, c) + (s3 - s2) * spacing_s * InTangent(t, k + 1, c);
}

Eigen::Quaterniond KeyQuaternion(const KeyTrack& t, size_t k) {
  return Eigen::Quaterniond(Value(t, k, 3), Value(t, k, 0), Value(t, k, 1), Value(t, k, 2)).normalized();
}

}  // namespace

std::optional<double> DetectFrameRate(const std::vector<double>& times_s) {
  for (double rate : kCandidateRatesHz) {
    bool fits = true;
    for (double t : times_s) {
      if (std::abs(t * rate - std::round(t * rate)) / rate > kFrameSnapToleranceS) {
        fits = false;
        break;
      }
    }
    if (fits) return rate;
  }
  return std::nullopt;
}

int64_t FrameCount(double last_time_s, double rate_hz) {
  // Clamped so that absurd durations stay representable; callers refuse them by size.
  const double frames = std::min(std::ceil(last_time_s * rate_hz - kFrameSnapToleranceS * rate_hz), 1e15);
  return std::max<int64_t>(0, static_cast<int64_t>(frames)) + 1;
}

std::vector<int> KeyedFrames(const KeyTrack& track, double rate_hz, int num_frames) {
  std::vector<int> frames;
  for (double u : KeyPositions(track.times_s, rate_hz)) {
    const int f = std::clamp(static_cast<int>(std::lround(u)), 0, num_frames - 1);
    if (frames.empty() || frames.back() != f) frames.push_back(f);
  }
  return frames;
}

std::vector<Eigen::Vector3d> KeyVectors(const KeyTrack& track) {
  std::vector<Eigen::Vector3d> out(track.times_s.size());
  for (size_t k = 0; k < out.size(); ++k) out[k] = {Value(track, k, 0), Value(track, k, 1), Value(track, k, 2)};
  return out;
}

std::vector<Eigen::Quaterniond> KeyQuaternions(const KeyTrack& track) {
  std::vector<Eigen::Quaterniond> out(track.times_s.size());
  for (size_t k = 0; k < out.size(); ++k) out[k] = KeyQuaternion(track, k);
  return out;
}

std::vector<Eigen::Vector3d> SampleVector3(const KeyTrack& track, double rate_hz, int num_frames) {
  const std::vector<double> positions = KeyPositions(track.times_s, rate_hz);
  SegmentFinder finder(positions);
  std::vector<Eigen::Vector3d> out(num_frames);
  for (int f = 0; f < num_frames; ++f) {
    const Segment seg = finder.At(f);
    for (int c = 0; c < 3; ++c) {
      if (seg.s == 0.0 || track.interpolation == Interpolation::kStep) {
        out[f][c] = Value(track, seg.k, c);
      } else if (track.interpolation == Interpolation::kLinear) {
        out[f][c] = (1 - seg.s) * Value(track, seg.k, c) + seg.s * Value(track, seg.k + 1, c);
      } else {
        const double spacing_s = (positions[seg.k + 1] - positions[seg.k]) / rate_hz;
        out[f][c] = Hermite(track, seg.k, seg.s, spacing_s, c);
      }
    }
  }
  return out;
}

std::vector<Eigen::Quaterniond> SampleRotation(const KeyTrack& track, double rate_hz, int num_frames) {
  const std::vector<double> positions = KeyPositions(track.times_s, rate_hz);
  SegmentFinder finder(positions);
  std::vector<Eigen::Quaterniond> out(num_frames);
  for (int f = 0; f < num_frames; ++f) {
    const Segment seg = finder.At(f);
    if (seg.s == 0.0 || track.interpolation == Interpolation::kStep) {
      out[f] = KeyQuaternion(track, seg.k);
    } else if (track.interpolation == Interpolation::kLinear) {
      // Eigen's slerp takes the short arc, as the glTF spec asks.
      out[f] = KeyQuaternion(track, seg.k).slerp(seg.s, KeyQuaternion(track, seg.k + 1)).normalized();
    } else {
      const double spacing_s = (positions[seg.k + 1] - positions[seg.k]) / rate_hz;
      Eigen::Vector4d q;
      for (int c = 0; c < 4; ++c) q[c] = Hermite(track, seg.k, seg.s, spacing_s, c);
      // A spline through opposite quaternions can pass near zero; fall back to the key then.
      out[f] = q.norm() > 1e-9 ? Eigen::Quaterniond(q[3], q[0], q[1], q[2]).normalized() : KeyQuaternion(track, seg.k);
    }
  }
  return out;
}

}  // namespace mocapfill::gltf_internal
