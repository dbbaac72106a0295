// A sampled animation of one skeleton, plus which joints the source keyed at which
// frames. Every stage of mocapfill passes clips in this form; keys from sparse sources
// (a glTF sketch) are interpolated onto a uniform frame grid on import, and the keyed
// frames are remembered because the fill stages depend on them, together with the
// source's exact key times and values (which the grid may not hold). Clips are uniformly
// sampled unless frame_times_s says otherwise (an output resampled to a sketch's own,
// possibly irregular, key times); most stages require uniform clips.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "processing/core/skeleton.h"
#include "processing/core/status.h"

namespace mocapfill {

// The most frames x joints a motion read from a file may have: 20 million joint-frames is
// about 1.1 GB of transforms (56 bytes each) and over an hour of a 31-joint capture at
// 120 Hz. Every reader refuses a larger motion, whatever the file declares, rather than
// swapping to death.
constexpr int64_t kMaxMotionJointFrames = 20'000'000;

// Frames (indices into the clip) at which the source had a key, per joint and property.
// Sorted ascending, no duplicates. A joint with neither rotation nor translation keys
// is "missing": the fill stages synthesise it.
//
// The exact keys: the source's key times (seconds, strictly increasing, >= 0) and local
// values (unit quaternions; metres, after the importer's unit and axis conversion, so they
// compare with the clip's samples), one value per time. CUBICSPLINE keys give their value
// part. Empty when the source is baked (BVH: every frame is a key, at its frame time) or
// unknown; then the keyed frames' times and samples are the keys.
struct JointKeys {
  std::vector<int> rotation_frames;
  std::vector<int> translation_frames;
  std::vector<double> rotation_times_s;
  std::vector<Eigen::Quaterniond> rotation_values;
  std::vector<double> translation_times_s;
  std::vector<Eigen::Vector3d> translation_values;
  // No keyed frames (the exact keys never come without keyed frames).
  bool empty() const { return rotation_frames.empty() && translation_frames.empty(); }
  bool has_exact_rotations() const { return !rotation_times_s.empty(); }
  bool has_exact_translations() const { return !translation_times_s.empty(); }
};

struct MotionClip {
  std::string name;
  double sample_rate_hz = 30.0;  // frames per second; frame f is at time f / sample_rate_hz (s)
  int num_frames = 0;
  int num_joints = 0;
  // Empty: uniform, frame f at f / sample_rate_hz. Otherwise explicit sample times (s), one
  // per frame, strictly increasing, starting at 0; sample_rate_hz is then only nominal (the
  // rate the clip was made from). Stages that need a uniform clip refuse one with
  // kInvalidArgument; ResampleClip brings it onto a grid.
  std::vector<double> frame_times_s;

  // Local joint transforms, frame-major: index f * num_joints + j. Rotations are unit
  // quaternions, hemisphere-continuous over time per joint. Translations are in metres;
  // joints whose translation never varies hold their rest translation at every frame.
  std::vector<Eigen::Quaterniond> rotations;
  std::vector<Eigen::Vector3d> translations;
  // Per joint: 1 when the translation varies over the clip (root motion, stretchy joints).
  std::vector<std::uint8_t> translation_animated;
  // Per joint keys as the source had them (every frame for baked sources such as BVH).
  std::vector<JointKeys> keys;

  // Allocates a clip of `frames` frames holding the skeleton's rest pose, with no keys.
  static MotionClip RestPose(const Skeleton& skeleton, int frames, double rate_hz);

  bool uniform() const { return frame_times_s.empty(); }
  double duration_s() const { return num_frames > 1 ? time_s(num_frames - 1) : 0.0; }
  double time_s(int frame) const {
    return frame_times_s.empty() ? frame / sample_rate_hz : frame_times_s[static_cast<size_t>(frame)];
  }

  Eigen::Quaterniond& rotation(int frame, int joint) { return rotations[frame * num_joints + joint]; }
  const Eigen::Quaterniond& rotation(int frame, int joint) const { return rotations[frame * num_joints + joint]; }
  Eigen::Vector3d& translation(int frame, int joint) { return translations[frame * num_joints + joint]; }
  const Eigen::Vector3d& translation(int frame, int joint) const { return translations[frame * num_joints + joint]; }

  // Marks every joint keyed at every frame (a fully baked source).
  void KeyAllFrames();
  // Flips rotations so every joint's track is hemisphere-continuous.
  void MakeContinuous();
  // Sets translation_animated from the data: a joint is animated when any frame differs
  // from frame 0 by more than tolerance_m.
  void DetectAnimatedTranslations(double tolerance_m = 1e-9);

  // Checks sizes, finiteness and unit rotations against the skeleton; explicit frame times
  // (one per frame, finite, strictly increasing from 0) and exact keys (one value per time,
  // finite, times strictly increasing and >= 0).
  Status Validate(const Skeleton& skeleton) const;
};

// OK for a uniform clip; kInvalidArgument naming `stage` and the clip for one with explicit
// frame times (which the stage cannot process: resample it to a rate first).
Status RequireUniform(const MotionClip& clip, const std::string& stage);

}  // namespace mocapfill
