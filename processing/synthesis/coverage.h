// Coverage of a sketch by the database: where the nearest database fragment of a
// sketch fragment leaves much of the fragment's motion unexplained, the database does not
// hold that motion and what the fragment methods synthesise there is a guess. Such stretches
// are reported and their channels blended towards a safe prior (the database mean pose by
// default), which scored better there than the guess. The score is relative to the fragment's
// own motion rather than to the database's distances between its takes because the latter
// did not separate covered from uncovered sketches (docs/fill.md, Coverage); that ratio is
// reported alongside.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/synthesis/fragment_fill_options.h"
#include "processing/synthesis/fragment_fill_report.h"
#include "processing/synthesis/fragment_matching.h"
#include "processing/synthesis/matching_database.h"

namespace mocapfill {

// The takes yardstick: the median distance (not squared) from an evenly spaced sample of the
// database's fragments (options.coverage.reference_fragments) to their nearest admissible
// fragment of another clip, on the driven channels. 0 when no fragment has one (one clip).
double ReferenceDistance(const MatchingDatabase& mdb, const std::vector<DrivenChannel>& driven,
                         const FragmentFillOptions& options);

// Per sketch fragment: the squared distance of its nearest candidate (`nearest[f]`
// ascending, as MatchFragments returns), its share of `energies[f]` (FragmentEnergies), its
// ratio to `reference` (ReferenceDistance), the prior's and the texture's weights (0 below
// their poor threshold, 1 from their none threshold on, smooth in between; 0 everywhere when
// blending is off); and the poorly covered stretches.
CoverageReport MeasureCoverage(const std::vector<SketchFragment>& fragments,
                               const std::vector<std::vector<Candidate>>& nearest, const std::vector<float>& energies,
                               double reference, const CoverageOptions& options);

// The median of the fragments' unexplained shares (the upper one of an even count); 0 when
// there is no fragment.
double MedianUnexplained(const CoverageReport& coverage);

// A per-fragment weight (FragmentCoverage::prior_weight or ::texture_weight) at every frame:
// each fragment's weight at its middle frame, linear in between, held before the first middle
// and after the last (no step at fragment seams).
Eigen::VectorXd WeightPerFrame(const CoverageReport& coverage, double FragmentCoverage::*weight, int frames);

// out(f, c) <- (1 - w(f)) out(f, c) + w(f) prior(f, c) for the listed channels.
void BlendTowards(const Eigen::MatrixXd& prior, const Eigen::VectorXd& weight, const std::vector<int>& channels,
                  Eigen::MatrixXd& out);

}  // namespace mocapfill
