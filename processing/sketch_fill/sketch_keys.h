// The sketch's keys in the fill use case: which joints stay keyed, which translation keys are
// acceptable, at which times the output is sampled, and how the output is pinned to the keys
// at the animator's exact key times. Internal to mocapfill_sketch_fill.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"
#include "processing/motion/key_fidelity.h"
#include "processing/motion/two_bone_ik.h"

namespace mocapfill {

// `synthesize` drops the keys of the listed joints; `keep` drops the keys of every other
// joint. kInvalidArgument naming a joint the skeleton lacks.
Status ApplyKeyOverrides(const Skeleton& skeleton, const std::vector<std::string>& keep,
                         const std::vector<std::string>& synthesize, MotionClip& clip);

// Joints other than `hips` and its ancestors that carry translation keys moving them away
// from their rest offset are refused (kInvalidData saying what the keys would do), unless
// they are listed in `position_keys`.
Status CheckTranslationKeys(const Skeleton& skeleton, const MotionClip& clip, int hips,
                            const std::vector<std::string>& position_keys);

// Output sample times: the frames of `rate_hz` over the sketch's duration, plus every key
// time that is not on that grid (then `uniform` is false).
std::vector<double> OutputTimes(const MotionClip& sketch, double rate_hz, bool& uniform);

// Moves every keyed joint of `out` (same skeleton as `sketch`, frame times containing every
// key time) onto its keys with a displacement map: the offset at each key, interpolated
// between keys (held before the first and after the last), so that the output passes
// exactly through each key and keeps its own detail in between.
void PinKeys(const MotionClip& sketch, int hips, MotionClip& out);

// A world position a joint must reach at a time (a --position-keys key, on the sketch's rig),
// and the limb that moves it there.
struct PositionTarget {
  int joint = -1;
  double time_s = 0.0;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  TwoBoneChain chain;  // chain.end == joint
};

// Moves each target's joint onto its positions with two-bone IK (two_bone_ik.h) at the target
// times, as a displacement map of the chain's rotations between those times (held before the
// first and after the last), so that the limb passes exactly through each position and keeps
// the fill's motion in between. `out`'s frame times contain every target time.
void PinPositionTargets(const Skeleton& skeleton, const std::vector<PositionTarget>& targets, MotionClip& out);

// Largest rotation change of any joint between consecutive frames, in degrees; and per joint.
double MaxFrameJumpDeg(const MotionClip& clip);
std::vector<double> MaxFrameJumpsDeg(const MotionClip& clip);

}  // namespace mocapfill
