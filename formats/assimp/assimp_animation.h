// One aiAnimation to one uniformly sampled MotionClip over the imported skeleton.
// Internal to formats/assimp (Assimp types forward-declared only).
#pragma once

#include <string>
#include <vector>

#include "formats/assimp/assimp_node_graph.h"
#include "processing/core/motion_clip.h"
#include "processing/core/status.h"

struct aiAnimation;

namespace mocapfill::assimp_detail {

// Samples `anim` at `rate_hz` (0: the lowest common rate on which every key lies, see
// DetectKeyRateHz). Ticks become seconds with mTicksPerSecond (25 when the file gives 0);
// a negative first key shifts the clip to start at 0. Joint transforms are the product
// of their chain's node transforms, each animated node interpolated linearly (slerp for
// rotations) and held before the first and after the last key. Key frames are recorded
// per joint (translation keys of every animated node in the chain; translation_animated
// is left for the caller to set once lengths are in metres). Lengths stay in source
// units. `index` names unnamed animations.
Result<MotionClip> ConvertAnimation(const aiAnimation& anim, int index, const NodeGraph& graph,
                                    const Skeleton& skeleton, double rate_hz, std::vector<std::string>& warnings);

}  // namespace mocapfill::assimp_detail
