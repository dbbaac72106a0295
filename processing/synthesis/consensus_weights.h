// Where a group's candidates disagree on its posture. The blend weights each candidate by how
// well it matches the sketch, and its weighted mean is the least-squares estimate of the
// group's pose. The fill's remaining error is mostly a posture held over a whole take (the
// held-out style's arm carriage, docs/fill.md), and what is measured and seen is a distance,
// not its square: the point nearest in summed distance to the candidates is their geometric
// median, which a few takes carrying their arms far from the others pull much less than the
// mean. Weiszfeld's iteration reaches it by dividing each candidate's weight by its distance
// from the current estimate. Here the estimate is the take's consensus, the group's joint
// positions as the blend puts them averaged over the whole fill, and a candidate's distance is
// that of its own positions averaged over its fragment: a take whose carriage differs from
// what the candidates agree on over the whole motion counts less, in every fragment.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/synthesis/assembly.h"

namespace mocapfill {

// Per database frame (rows of db.signals()), the positions of the joints placed by the rotations
// of `group` (every child of a group joint), relative to the group's first joint, in that
// joint's parent frame (metres), 3 columns per placed joint. `group` lists parents before
// children and its first joint is the ancestor of the others.
Eigen::MatrixXf GroupPositions(const MotionDatabase& db, const std::vector<int>& group);

// The blend weights of `in` (in.weights, or DistanceWeights when null: per fragment, over its
// BlendSet) after `iterations` Weiszfeld steps towards the candidates' geometric median in
// `positions` (GroupPositions). The consensus is every fragment's blend of its candidates'
// positions averaged over their own fragment, averaged over the fragments by length; each
// candidate's starting weight is divided by its distance from it (root mean square over the
// placed joints), floored at `floor_m` (candidates that close count as they were). Each
// fragment's weights still sum to 1. in.source, in.channels and in.crossfade are not used.
std::vector<std::vector<double>> ConsensusWeights(const AssemblyInputs& in, const Eigen::MatrixXf& positions,
                                                  int iterations, double floor_m);

}  // namespace mocapfill
