// Planted feet between keys. Keyed legs interpolated between their keys (and a root
// interpolated linearly) make a standing foot slide: where a foot stands low and still at two
// consecutive keys, it is in contact with the ground all the way between them, so the foot is
// held on the line between its two keyed positions by two-bone IK of its leg (two_bone_ik.h),
// frame by frame. At the keys the correction is zero, so keys stay exact and the legs do not
// pop where a contact starts or ends.
#pragma once

#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/motion/two_bone_ik.h"
#include "processing/retargeting/rig_mapping.h"

namespace mocapfill {

struct LegForPlanting {
  std::string side;    // "left" / "right", for reports
  TwoBoneChain chain;  // thigh, shin, foot
  // The times (seconds) at which the animator fixed this foot's position: its leg and the
  // root keyed together.
  std::vector<double> key_times_s;
};

struct FootPlantOptions {
  double max_height_m = 0.05;  // a foot standing: within this of its lowest keyed height
  double max_slide_m = 0.05;   // and moving less than this, horizontally, from one key to the next
};

struct FootContact {
  std::string side;
  double start_s = 0.0;  // the two keys that bound the contact
  double end_s = 0.0;
  double max_correction_m = 0.0;  // largest IK move of the foot inside the contact
};

struct FootPlantReport {
  std::vector<FootContact> contacts;
  int frames_held = 0;  // leg-frames corrected
  double max_correction_m = 0.0;
};

// The times at which every one of `joints` has a rotation key (RotationKeysOf), ascending.
std::vector<double> JointlyKeyedTimes(const MotionClip& clip, const std::vector<int>& joints);

// A rig's legs for planting (thigh, shin and foot by its humanoid mapping), each with the
// times at which `sketch` keys the hips and the whole leg together: where the animator fixed
// the foot.
std::vector<LegForPlanting> LegsToPlant(const RigMapping& mapping, const MotionClip& sketch, int hips);

// Plants every leg's foot in `clip` (uniform or explicit frame times; every key time is a frame).
FootPlantReport PlantFeet(const Skeleton& skeleton, const std::vector<LegForPlanting>& legs,
                          const FootPlantOptions& options, MotionClip& clip);

}  // namespace mocapfill
