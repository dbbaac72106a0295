// Assembly of the synthesised channels from the chosen database fragments and seam smoothing
// (Pullen and Bregler 2002; thesis 4.5). Texturing and re-pinning of keys, which follow, are in
// processing/texturing.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/synthesis/fragment_matching.h"
#include "processing/synthesis/matching_database.h"

namespace mocapfill {

struct AssemblyInputs {
  const MotionDatabase* db = nullptr;
  const MatchingDatabase* mdb = nullptr;
  const std::vector<SketchFragment>* fragments = nullptr;
  const std::vector<std::vector<Candidate>>* candidates = nullptr;  // ascending distance
  std::vector<int> leads;        // joined candidate per fragment
  int blend = 1;                 // candidates averaged per fragment (the lead always among them)
  std::vector<int> channels;     // channels to write
  double crossfade = 0.0;        // overlap beyond each fragment, share of its length per side
  // What is blended: columns `channels` of this (rows: the database's frames); null: the
  // database's signals. The fill also blends the takes' foot contacts (ground_contacts.h).
  const Eigen::MatrixXf* source = nullptr;
  // Per fragment, the weight of each candidate of its BlendSet (summing to 1); null: DistanceWeights.
  const std::vector<std::vector<double>>* weights = nullptr;
};

// The candidates blended into one fragment: the nearest `blend`, with the lead replacing the
// farthest when it is not among them.
std::vector<int> BlendSet(const std::vector<Candidate>& cands, int lead, int blend);

// Weights exp(-d / mean d) over the set, normalised to sum 1.
std::vector<double> DistanceWeights(const std::vector<Candidate>& cands, const std::vector<int>& set);

// Writes `channels` of every fragment's frames into `out` (frames x channels): the candidates'
// captured signals stretched linearly to the fragment's length, averaged over the lead and the
// nearest others with `weights` (by default exp(-d / mean d), DistanceWeights). Without
// cross-fade a fragment owns [first, last) (the last one its end frame too); with it, each
// fragment's candidates extend `crossfade` of its length beyond both ends (the takes continue
// there) and overlapping fragments are mixed with smoothstep fade weights, so there is no seam
// to smooth. Returns how many candidates each fragment blended.
std::vector<int> AssembleFragments(const AssemblyInputs& in, Eigen::MatrixXd& out);

// Seam smoothing: at every fragment boundary b, each listed channel's jump beyond the expected
// step is split between both sides with a quadratic falloff over `window_frames` (capped at
// half of each adjoining fragment), so values and slopes meet.
void SmoothSeams(Eigen::MatrixXd& out, const std::vector<int>& channels, const std::vector<SketchFragment>& fragments,
                 int window_frames);

}  // namespace mocapfill
