// Two-bone inverse kinematics (thigh and shin to a foot target, upper arm and forearm to a
// hand target), analytic: the middle joint bends within the chain's own plane until the chain
// spans the distance to the target, then the upper joint turns the chain onto it. Bones keep
// their lengths; the end joint keeps its world orientation (a placed foot stays as it was
// turned). Used to hold world-position keys exactly on the user's own rig.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "processing/core/kinematics.h"
#include "processing/core/skeleton.h"

namespace mocapfill {

// Three joints down one limb: `lower` descends from `upper`, `end` from `lower` (twist joints
// in between are carried along).
struct TwoBoneChain {
  int upper = -1;
  int lower = -1;
  int end = -1;
};

struct TwoBoneSolution {
  // New local rotations of the chain's joints.
  Eigen::Quaterniond upper = Eigen::Quaterniond::Identity();
  Eigen::Quaterniond lower = Eigen::Quaterniond::Identity();
  Eigen::Quaterniond end = Eigen::Quaterniond::Identity();
  // How far the end stays from the target (metres): 0 unless the target is out of the chain's
  // reach (then the chain stretches straight towards it).
  double miss_m = 0.0;
};

// The axis the middle joint bends about, in the upper joint's frame, taken where `clip` bends
// the limb most: a nearly straight leg shows no bend plane of its own, and a plane taken from
// it could flip from one frame to the next (the knee would snap backwards).
Eigen::Vector3d HingeOf(const Skeleton& skeleton, const MotionClip& clip, const TwoBoneChain& chain);

// The rotations that put `chain.end` at `target` (world, metres), starting from `pose` (the
// world pose of the frame being solved), bending about `hinge` (HingeOf; zero: the plane the
// chain lies in at `pose`).
TwoBoneSolution SolveTwoBoneIk(const Skeleton& skeleton, const WorldPose& pose, const TwoBoneChain& chain,
                               const Eigen::Vector3d& target,
                               const Eigen::Vector3d& hinge = Eigen::Vector3d::Zero());

}  // namespace mocapfill
