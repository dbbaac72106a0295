// A uniformly sampled animation of one skeleton, plus which joints the source keyed
// at which frames. Every stage of mocapfill passes clips in this form; keys from
// sparse sources (a glTF sketch) are interpolated onto the frame grid on import, and
// the keyed frames are remembered because the fill stages depend on them.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "processing/core/skeleton.h"
#include "processing/core/status.h"

namespace mocapfill {

// Frames (indices into the clip) at which the source had a key, per joint and property.
// Sorted ascending, no duplicates. A joint with neither rotation nor translation keys
// is "missing": the fill stages synthesise it.
struct JointKeys {
  std::vector<int> rotation_frames;
  std::vector<int> translation_frames;
  bool empty() const { return rotation_frames.empty() && translation_frames.empty(); }
};

struct MotionClip {
  std::string name;
  double sample_rate_hz = 30.0;  // frames per second; frame f is at time f / sample_rate_hz (s)
  int num_frames = 0;
  int num_joints = 0;

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

  double duration_s() const { return num_frames > 1 ? (num_frames - 1) / sample_rate_hz : 0.0; }
  double time_s(int frame) const { return frame / sample_rate_hz; }

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

  // Checks sizes, finiteness and unit rotations against the skeleton.
  Status Validate(const Skeleton& skeleton) const;
};

}  // namespace mocapfill
