// Keyframe tracks as glTF stores them (key times in seconds, LINEAR / STEP / CUBICSPLINE
// values) and their resampling onto a uniform frame grid. No tinygltf types: the reader
// converts samplers into KeyTrack first, so this part is testable on its own.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <vector>

namespace mocapfill::gltf_internal {

enum class Interpolation { kLinear, kStep, kCubicSpline };

struct KeyTrack {
  std::vector<double> times_s;  // strictly increasing, finite, >= 0
  // `components` values per key; CUBICSPLINE stores (in-tangent, value, out-tangent) per key.
  std::vector<double> values;
  int components = 3;
  Interpolation interpolation = Interpolation::kLinear;
};

// Two key times closer than this (seconds) to a frame of the grid are on that frame.
constexpr double kFrameSnapToleranceS = 1e-4;

// The lowest of 24, 25, 30, 48, 50, 60, 100, 120, 240 Hz on whose grid every time lies
// within kFrameSnapToleranceS, or nullopt.
std::optional<double> DetectFrameRate(const std::vector<double>& times_s);

// Number of frames at `rate_hz` covering [0, last_time_s] (the last key is reached, not cut).
int64_t FrameCount(double last_time_s, double rate_hz);

// Frames at which the track has keys (nearest frame for keys off the grid), ascending,
// unique, clamped to [0, num_frames).
std::vector<int> KeyedFrames(const KeyTrack& track, double rate_hz, int num_frames);

// The value part of every key (CUBICSPLINE: the middle of each triplet) as the clip holds
// it: vectors as stored, quaternions normalised (x, y, z, w order in the track).
std::vector<Eigen::Vector3d> KeyVectors(const KeyTrack& track);
std::vector<Eigen::Quaterniond> KeyQuaternions(const KeyTrack& track);

// Samples a vector track (translation, scale) at frames 0..num_frames-1 of `rate_hz`.
// Before the first key and after the last the end values hold.
std::vector<Eigen::Vector3d> SampleVector3(const KeyTrack& track, double rate_hz, int num_frames);

// Samples a rotation track (x, y, z, w quaternions): slerp for LINEAR, Hermite then
// renormalisation for CUBICSPLINE. Results are unit quaternions.
std::vector<Eigen::Quaterniond> SampleRotation(const KeyTrack& track, double rate_hz, int num_frames);

}  // namespace mocapfill::gltf_internal
