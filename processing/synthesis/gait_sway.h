// Which foot a walk stands on, as the hips show it. Synthesised legs are matched on the keyed
// hips (their tilt and the root's travel), yet a take can fit those and still step on the
// other foot: the fill's left foot then stands where the capture's right one did, and swings
// where the capture's foot is planted. The hips sway over the stance foot in every style
// (measured on the captured walks: the hips' lateral offset from the feet's midpoint against
// "the left foot stands" correlates +0.78 to +0.87 over eight styles), while the pelvis's yaw,
// which the root features' lateral velocity is measured in, turns with or against the stance
// by style. So the sway is measured against the path rather than the pelvis: the root's
// lateral offset from its own position averaged over half a second on either side, along the
// averaged heading's lateral axis; and a moving fragment's leg candidates that sway otherwise
// than the sketch are ranked further down (FragmentFillOptions::leg_sway_weight).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/synthesis/fragment_matching.h"
#include "processing/synthesis/matching_database.h"

namespace mocapfill {

// The path the sway is measured from: the root averaged over this long on either side (a
// stride at a walk, so the sway itself averages out of it).
constexpr double kSwayHalfWindowS = 0.5;

// Per frame, the root's lateral offset (metres) from its position averaged over `half_window`
// frames on either side (clamped at the ends), along the lateral axis of the heading averaged
// the same way. `root_features`: frames x kNumRootFeatures (tangent_space.h).
Eigen::VectorXd LateralSway(const Eigen::MatrixXd& root_features, double rate_hz, int half_window);

// LateralSway of every database clip, rows as db.signals().
Eigen::VectorXd DatabaseSway(const MotionDatabase& db, int half_window);

// How alike two stretches of sway are: the cosine of 8 samples taken evenly over each (frames
// first..last of each, inclusive), 1 swaying alike, -1 on the other foot, 0 with no sway.
double SwayAgreement(const Eigen::VectorXd& a, int a_first, int a_last, const Eigen::VectorXd& b, int b_first,
                     int b_last);

// For each fragment i with use[i] != 0: each candidate's distance is multiplied by
// 1 + weight * (1 - agreement) / 2 (agreement of the sketch's sway over the fragment with the
// candidate take's over its own frames), and the candidates are sorted again by distance.
void RankBySway(const MatchingDatabase& mdb, const MotionDatabase& db, const std::vector<SketchFragment>& fragments,
                const std::vector<int>& use, const Eigen::VectorXd& sketch_sway, const Eigen::VectorXd& db_sway,
                double weight, std::vector<std::vector<Candidate>>& candidates);

}  // namespace mocapfill
