// Sketches as an animator's tool exports them: a glTF whose keyed joints have channels with
// keys only at the chosen times (any rate, or irregular), every other joint no channel.
// Written with tinygltf (not mocapfill's writer), so the reader meets a foreign file.
#pragma once

#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"

namespace mocapfill::testing {

// Writes `path` (.gltf) with the skeleton's nodes and, for each joint in `joints`, a rotation
// channel keyed at `key_times_s` with `clip`'s rotations there (interpolated between its
// frames); the joints with animated translation among them get a translation channel too.
bool WriteSparseSketch(const Skeleton& skeleton, const MotionClip& clip, const std::vector<std::string>& joints,
                       const std::vector<double>& key_times_s, const std::string& path);

// Key times every `step_s` from 0 to the clip's end (inclusive of the last whole step).
std::vector<double> EveryStep(double duration_s, double step_s);

}  // namespace mocapfill::testing
