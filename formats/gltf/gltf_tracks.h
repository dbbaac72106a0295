// How an exported .glb stores one clip's samples, and the float32 packing of each sample.
// WriteGlb packs them from a MotionClip; the streaming BVH converter (formats/fast_convert/bvh_to_glb.h)
// packs them while it parses, with these same functions, so both give the same bytes.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "processing/core/status.h"

namespace mocapfill {

// Float32 tracks, one after the other with no gaps: the frame times; every joint's
// rotations (x, y, z, w per frame); then the translations (x, y, z per frame) of the
// `moving` joints whose translation is animated, in joint order. Offsets count floats.
struct ClipTrackLayout {
  size_t frames = 0;
  size_t joints = 0;
  size_t moving = 0;

  size_t RotationTrack(size_t joint) const { return frames + 4 * frames * joint; }
  size_t TranslationTrack(size_t k) const { return frames * (1 + 4 * joints) + 3 * frames * k; }
  size_t TotalFloats() const { return frames * (1 + 4 * joints + 3 * moving); }
};

// Frame f at f / rate_hz seconds, computed in double and rounded to float32; fails when two
// frames round to the same float32 time (the clip is too long for its rate).
Status PackFrameTimes(const std::string& clip_name, size_t frames, double rate_hz, float* times);

// Explicit frame times (MotionClip::frame_times_s, seconds) rounded to float32; fails when
// two of them round to the same float32 time.
Status PackExplicitFrameTimes(const std::string& clip_name, const double* times_s, size_t frames, float* times);

// One rotation as the track stores it: normalised (unless its squared length is within
// kRotationUnitTolerance of 1 already, as a composed rotation's is to an ulp or two: dividing by
// such a length moves a value by less than the float32 rounding after it), turned to the
// hemisphere of `previous` (the joint's packed rotation one frame earlier, zero before the
// first frame; updated here) and rounded to float32. The rounding leaves the length within
// about 1e-7 of 1, far inside what glTF readers and the validator accept (0.00769), so
// the float32 values are not renormalised: that would move them by an ulp at most, at the
// cost of a division each. The sums run in the order Eigen's SSE2 code adds a
// Vector4d's terms, (x + z) + (y + w): these are its squaredNorm() and dot() written out,
// bit for bit, so that PackRotations can do the same four lanes at once.
inline constexpr double kRotationUnitTolerance = 1e-12;
inline void PackRotation(const Eigen::Quaterniond& q, Eigen::Vector4d& previous, float* out) {
  const auto sum = [](const double* a) { return (a[0] + a[2]) + (a[1] + a[3]); };
  double v[4] = {q.x(), q.y(), q.z(), q.w()};
  const double squares[4] = {v[0] * v[0], v[1] * v[1], v[2] * v[2], v[3] * v[3]};
  const double n2 = sum(squares);
  if (n2 > 0.0 && std::abs(n2 - 1.0) > kRotationUnitTolerance) {
    const double n = std::sqrt(n2);
    for (double& c : v) c /= n;
  }
  const double products[4] = {v[0] * previous[0], v[1] * previous[1], v[2] * previous[2], v[3] * previous[3]};
  if (sum(products) < 0)
    for (double& c : v) c = -c;
  previous = Eigen::Vector4d(v[0], v[1], v[2], v[3]);
  for (int c = 0; c < 4; ++c) out[c] = static_cast<float>(v[c]);
}

// PackRotation of `count` joints of one frame: q[j] with previous[j] into out + j * stride
// (stride in floats: one track to the next). The same bits, four lanes at a time with AVX2
// where the CPU has it.
void PackRotations(const Eigen::Quaterniond* q, size_t count, Eigen::Vector4d* previous, float* out, size_t stride);

// PackRotations of the joints listed in joints[0, count) only, each j as above (q[j],
// previous[j], out + j * stride); the others are left alone.
void PackListedRotations(const Eigen::Quaterniond* q, const uint32_t* joints, size_t count, Eigen::Vector4d* previous,
                         float* out, size_t stride);

// One translation (metres) as the track stores it.
inline void PackTranslation(const Eigen::Vector3d& t, float* out) {
  for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(t[c]);
}

}  // namespace mocapfill
