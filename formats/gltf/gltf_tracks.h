// How an exported .glb stores one clip's samples, and the float32 packing of each sample.
// WriteGlb packs them from a MotionClip; the streaming BVH converter (formats/bvh_glb)
// packs them while it parses, with these same functions, so both give the same bytes.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstddef>
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

// One rotation as the track stores it: normalised, turned to the hemisphere of `previous`
// (the joint's packed rotation one frame earlier, zero before the first frame; updated
// here), rounded to float32 and normalised again in double, since the glTF validator
// checks the length of the float32 values.
inline void PackRotation(const Eigen::Quaterniond& q, Eigen::Vector4d& previous, float* out) {
  Eigen::Vector4d v = Eigen::Vector4d(q.x(), q.y(), q.z(), q.w()).normalized();
  if (v.dot(previous) < 0) v = -v;
  previous = v;
  const Eigen::Vector4d rounded = v.cast<float>().cast<double>();
  const Eigen::Vector4f unit = (rounded / rounded.norm()).cast<float>();
  for (int c = 0; c < 4; ++c) out[c] = unit[c];
}

// One translation (metres) as the track stores it.
inline void PackTranslation(const Eigen::Vector3d& t, float* out) {
  for (int c = 0; c < 3; ++c) out[c] = static_cast<float>(t[c]);
}

}  // namespace mocapfill
