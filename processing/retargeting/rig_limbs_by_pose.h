// Finding the legs and arms of a rig from its standing pose alone, for rigs whose joint names
// do not say which limb or which side a joint is ("Joint_12", or "Hand" under a "Left Hand"
// namespace the mapping cuts off): two chains hang from the hips down to the floor, two reach
// out sideways from the chest, and the longest two consecutive segments of each chain are the
// thigh and shin, or the upper arm and forearm. Sides come from the pose (toes ahead of the
// ankles give forward; left is up x forward), never from names.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "processing/retargeting/rig_structure.h"

namespace mocapfill {

struct LimbsByPose {
  int hips = -1;
  int upper_leg[2] = {-1, -1};  // [0] left, [1] right
  int hand[2] = {-1, -1};       // -1 when no two arms stand out sideways
  bool sides_seen = false;      // false: the pose shows no forward, [0] and [1] are arbitrary
};

// The limbs a standing pose (world positions, Y up, one per joint) shows, or nullopt with the
// reason in `why` when it shows no two legs under a hips joint. Joints named as helpers (end
// bones, twist halves, fingers) stay out of the chains.
std::optional<LimbsByPose> FindLimbsByPose(const RigStructure& rig, const std::vector<Eigen::Vector3d>& pose,
                                           std::string& why);

}  // namespace mocapfill
