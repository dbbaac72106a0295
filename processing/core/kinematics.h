// Forward kinematics: local joint transforms to world (model) space.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <span>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"

namespace mocapfill {

struct WorldPose {
  std::vector<Eigen::Vector3d> positions;       // per joint, metres
  std::vector<Eigen::Quaterniond> rotations;    // per joint
};

// A joint's offset from its parent in the rest pose as forward kinematics applies it: the
// parent's rest scale times the joint's rest translation. `joint` must have a parent.
Eigen::Vector3d RestOffset(const Skeleton& skeleton, int joint);

// World transforms of every joint at one frame (parents before children, one loop).
// Joint scale is applied to child offsets.
void ComputeWorldPose(const Skeleton& skeleton, const MotionClip& clip, int frame, WorldPose& out);

// World positions of every joint at every frame, frame-major [f * J + j].
std::vector<Eigen::Vector3d> ComputeWorldPositions(const Skeleton& skeleton, const MotionClip& clip);

// Each joint's mean local rotation over every frame of `clips` (MeanRotation's rule in one
// frame-major pass over all joints), except `root_joint`'s (-1: none): the mean of its world
// rotation with the heading taken off (SplitHeading), so that the way a performer faces does
// not enter the mean pose. Identity for every joint when there is no clip. The database's
// reference rotations and a clip's mean pose (a rig's rest) are both this.
std::vector<Eigen::Quaterniond> JointMeanRotations(const Skeleton& skeleton, std::span<const MotionClip* const> clips,
                                                   int root_joint);

// Extent of the rest pose (including BVH end sites) along axis `axis` (0 x, 1 y, 2 z),
// in the skeleton's own units. Used to guess units of unit-less formats.
double RestPoseExtent(const Skeleton& skeleton, int axis);

}  // namespace mocapfill
