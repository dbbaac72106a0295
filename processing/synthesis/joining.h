// Joining (thesis 4.6): one lead candidate per sketch fragment, by one of
// the thesis's three criteria. The cost matrix criterion solves a K x N trellis by dynamic
// programming, charging every seam the jump of the target channels between the end of one
// candidate and the start of the next (zero when the next continues the same take).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/synthesis/fragment_fill_options.h"
#include "processing/synthesis/fragment_matching.h"
#include "processing/synthesis/matching_database.h"

namespace mocapfill {

struct JoinInputs {
  const MotionDatabase* db = nullptr;
  const MatchingDatabase* mdb = nullptr;
  const std::vector<std::vector<Candidate>>* candidates = nullptr;  // per fragment, ascending
  std::vector<int> target_channels;   // channels the seams are measured on
  Eigen::VectorXf channel_sigma;      // per database channel, for normalising seam jumps
  double gamma = 0.5;                 // weight of the velocity jump
};

// Index into candidates[i] of the lead candidate of every fragment.
std::vector<int> JoinCandidates(JoinCriterion criterion, const JoinInputs& in);

// Whether database fragment b starts where a ends in the same take (no seam).
bool Continues(const DbFragment& a, const DbFragment& b);

}  // namespace mocapfill
