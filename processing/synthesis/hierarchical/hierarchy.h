// The hierarchical fragment method's plan (thesis 4.7): missing joints
// are grouped into limb chains, the groups are synthesised outward from the keyed joints in
// skeleton order, and each group is driven by the available joints it correlates with most.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/synthesis/fragment_matching.h"

namespace mocapfill {

struct JointGroup {
  std::string name;         // "Spine..Chest", "Shoulder_L..Hand_L"
  std::vector<int> joints;  // parents first
  int distance = 0;         // hierarchy distance from the nearest keyed joint (synthesis order)
};

// Chains of missing joints (a joint joins its parent's group when the parent is missing and
// has no other child), ordered by distance from the keyed joints, then by joint index.
std::vector<JointGroup> PlanGroups(const Skeleton& skeleton, const std::vector<std::uint8_t>& joint_keyed);

// The driven set of a group: up to max_joints available joints (0 = all) ranked by their
// strongest |correlation| with the group's channels in the database table times their weight
// (keyed 1, synthesised `synthesized_weight`), plus the root features when they are keyed.
// With root_drives a keyed motion root (its tilt) is always among the joints.
// `joint_available` / `joint_keyed` are per joint; `root_features_keyed` per the sketch.
std::vector<DrivenChannel> ChooseDrivers(const MotionDatabase& db, const JointGroup& group,
                                         const std::vector<std::uint8_t>& joint_available,
                                         const std::vector<std::uint8_t>& joint_keyed, bool root_features_keyed,
                                         int max_joints, double synthesized_weight, double root_feature_weight,
                                         bool root_drives = false);

// Channels (3 per joint) of a set of joints.
std::vector<int> JointChannels(const std::vector<int>& joints);

}  // namespace mocapfill
