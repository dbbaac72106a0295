// Where a blend of takes puts the hands. The fill averages the candidates' joint rotations,
// which puts a hand where the averaged shoulder and elbow angles reach: the arm at its full
// extension along a mean direction. The candidates' hands themselves average to a point
// nearer the body wherever they disagree (a wave raised in one take, hanging in the next),
// and that point is the least-squares estimate of where the hand is. The same blend
// (candidates, weights, stretching and cross-fades) is run on where each take has its hand
// relative to the shoulder, and the arm is then bent and turned (two-bone IK in the shoulder's
// frame) half way to that point (FragmentFillOptions::limb_reach): all the way lost again on
// gestures, where a blend of takes that disagree has a hand point that no one take reaches.
// The hand keeps its own rotation.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/core/motion_database.h"

namespace mocapfill {

// Two bones ending at a limb's tip (an arm: upper arm, forearm, hand).
struct Limb {
  int upper = -1;  // shoulder joint of the two bones (upper arm)
  int lower = -1;  // elbow (forearm)
  int end = -1;    // tip (hand)
};

// The rig's arms by its humanoid mapping (names and hierarchy): upper arm, forearm and hand
// where each is the next one's parent (a twist joint between them leaves the arm out). None
// for a rig that does not map to a humanoid.
std::vector<Limb> ArmsOf(const Skeleton& skeleton);

// Which of `limbs` (their indices) have all three joints among `joints`.
std::vector<int> LimbsWithin(const std::vector<Limb>& limbs, const std::vector<int>& joints);

// What the reach needs of a database's arms, found once per database (a pass over its frames).
struct ArmReach {
  std::vector<Limb> arms;                // ArmsOf the database's rig
  std::vector<Eigen::Vector3d> hinges;   // per arm, the elbow's axis in the upper joint's frame
  // Per database frame (rows of db.signals()), 3 columns per arm: the hand's position relative
  // to the upper-arm joint, in that joint's parent frame (metres).
  Eigen::MatrixXf table;
};
ArmReach PrepareArmReach(const MotionDatabase& db);

// Moves the channels of the upper and lower joints of the arms `which` (indices into
// prepared.arms) in `out` (fill frames x channels, tangent coordinates) so that each hand
// lands at `strength` of the way from where the channels put it to `reach` (fill frames x the
// table's columns), bending the elbow about its hinge and turning the upper joint; the hand's
// own channels stay.
void ReachLimbs(const MotionDatabase& db, const ArmReach& prepared, const std::vector<int>& which,
                const Eigen::MatrixXd& reach, double strength, Eigen::MatrixXd& out);

}  // namespace mocapfill
