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

// The limbs whose three joints are all among `joints`.
std::vector<Limb> LimbsWithin(const std::vector<Limb>& limbs, const std::vector<int>& joints);

// Per database frame (rows of db.signals()), 3 columns per limb: the tip's position relative
// to the upper joint, in the upper joint's parent frame (metres).
Eigen::MatrixXf LimbReachTable(const MotionDatabase& db, const std::vector<Limb>& limbs);

// Moves the channels of each limb's upper and lower joints in `out` (fill frames x channels,
// tangent coordinates) so that its tip lands at `strength` of the way from where the
// channels put it to `reach` (fill frames x 3 per limb, as LimbReachTable), bending the
// elbow about its anatomical hinge and turning the upper joint; the tip joint's own channels
// stay.
void ReachLimbs(const MotionDatabase& db, const std::vector<Limb>& limbs, const Eigen::MatrixXd& reach,
                double strength, Eigen::MatrixXd& out);

}  // namespace mocapfill
