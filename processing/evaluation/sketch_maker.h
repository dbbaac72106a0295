// Sketches made from ground truth for evaluation: a captured clip is reduced to what an
// animator would have keyed (some joints, every k frames), so that a fill method can be
// scored against the capture it came from.
#pragma once

#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"

namespace mocapfill {

struct SketchSpec {
  std::vector<std::string> keep_joints;  // joints keyed in the sketch, by name
  int key_every_frames = 8;              // key spacing; the last frame is always keyed too

  // Fails with kInvalidArgument naming the field.
  Status Validate() const;
};

// Key frames of a clip of `num_frames` frames at spacing `every`: 0, every, 2*every, ...,
// plus the last frame.
std::vector<int> SketchKeyFrames(int num_frames, int every);

// Keeps the listed joints at the key frames and drops every other joint: a kept joint's
// rotation (and its translation when animated) is interpolated between its keys as a glTF
// LINEAR sampler would import it (slerp, lerp); a dropped joint holds its rest rotation and
// has no keys; constant translations are copied from the capture. The topmost listed joints
// keep their world motion: an ancestor the capture animates (a root bone carrying the travel
// above the hips) is keyed with them. Errors: a listed joint the skeleton lacks, an empty clip
// (kInvalidArgument).
Result<MotionClip> MakeSketch(const Skeleton& skeleton, const MotionClip& truth, const SketchSpec& spec);

}  // namespace mocapfill
