// A humanoid's proportions in a rest pose, in metres: what `rig show` reports and what the
// retargeter scales root motion by (hip height).
#pragma once

#include "processing/core/skeleton.h"
#include "processing/retargeting/rest_pose.h"
#include "processing/retargeting/rig_mapping.h"

namespace mocapfill {

struct RigProportions {
  double hip_height = 0;  // hips above the lowest foot or toe joint (along +Y)
  double leg_length = 0;  // upper leg + lower leg (mean of the sides mapped)
  double arm_length = 0;  // upper arm + lower arm (mean of the sides mapped)
  double height = 0;      // lowest foot or toe joint to the head joint's highest descendant (along +Y)
};

RigProportions MeasureProportions(const Skeleton& skeleton, const RigMapping& mapping, const RigRest& rest);

}  // namespace mocapfill
