// Key fidelity: evaluating a clip at arbitrary times as a glTF viewer would (LINEAR: slerp
// and lerp between the neighbouring samples), and measuring how far a written clip is from
// a sketch's exact keys, at the keys' own times (not at frames of a grid they may miss).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"

namespace mocapfill {

// The frames around `time_s` and the fraction towards the second: (i, i + 1, u) with
// time_s(i) <= time_s < time_s(i + 1); (first, first, 0) before the first frame and
// (last, last, 0) from the last on. Uniform clips use their grid, explicit times a search.
struct FrameBracket {
  int a = 0;
  int b = 0;
  double u = 0.0;
};
FrameBracket FindBracket(const MotionClip& clip, double time_s);

// The frame whose time is nearest `time_s` (uniform or explicit frame times).
int NearestFrame(const MotionClip& clip, double time_s);

// A joint's keys at the source's exact times: its recorded key times and values where the
// importer kept them (JointKeys::rotation_times_s, ...), else its keyed frames at their frame
// times with the frame values.
struct RotationKeys {
  std::vector<double> times_s;
  std::vector<Eigen::Quaterniond> values;
};
struct TranslationKeys {
  std::vector<double> times_s;
  std::vector<Eigen::Vector3d> values;
};
RotationKeys RotationKeysOf(const MotionClip& clip, int joint);
TranslationKeys TranslationKeysOf(const MotionClip& clip, int joint);

// Joint `joint`'s local rotation at `time_s` seconds: slerp (short arc) between the two
// frames whose times (MotionClip::time_s, uniform or explicit) surround it; the first or
// last frame's value before the first and after the last frame. Unit quaternion.
// Preconditions: 0 <= joint < clip.num_joints, clip.num_frames >= 1, frame times increasing.
Eigen::Quaterniond SampleRotationAt(const MotionClip& clip, int joint, double time_s);

// Joint `joint`'s local translation (metres) at `time_s`: linear between the surrounding
// frames, clamped at the ends, as SampleRotationAt.
Eigen::Vector3d SampleTranslationAt(const MotionClip& clip, int joint, double time_s);

// The error at one joint's keys.
struct KeyError {
  std::string joint;             // the sketch's joint name
  int rotation_count = 0;        // rotation keys measured
  double rotation_mean_deg = 0;  // geodesic angle between key and written clip, degrees
  double rotation_max_deg = 0;
  double rotation_max_at_s = 0;  // the key time of the largest rotation error
  int translation_count = 0;     // translation keys measured
  double translation_mean_m = 0;  // distance between key and written clip, metres
  double translation_max_m = 0;
  double translation_max_at_s = 0;
};

struct KeyErrors {
  std::vector<KeyError> joints;  // every sketch joint with keys and a match, sketch order
  // Over every key of every joint.
  int rotation_count = 0;
  double rotation_mean_deg = 0;
  double rotation_max_deg = 0;
  int translation_count = 0;
  double translation_mean_m = 0;
  double translation_max_m = 0;
  // Sketch joints with keys that the written skeleton does not have (not measured).
  std::vector<std::string> unmatched_joints;
};

// For every joint with keys in `sketch`: its keys (RotationKeysOf, TranslationKeysOf);
// `written` is evaluated at their times with
// SampleRotationAt / SampleTranslationAt and compared. Joints are matched by name between
// `written_skeleton` and `sketch_skeleton`.
// Errors: either clip invalid for its skeleton (as MotionClip::Validate).
Result<KeyErrors> MeasureKeyErrors(const Skeleton& written_skeleton, const MotionClip& written,
                                   const Skeleton& sketch_skeleton, const MotionClip& sketch);

// The same with one skeleton shared by both clips (joints match by index, hence by name).
Result<KeyErrors> MeasureKeyErrors(const Skeleton& skeleton, const MotionClip& written, const MotionClip& sketch);

}  // namespace mocapfill
