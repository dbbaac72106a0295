// Fragmentation of the sketch and matching of its fragments against the database
// (thesis 4.3-4.4): the sketch is cut where the master channel's band
// changes direction, and every sketch fragment is compared with every database fragment of
// the same direction and a similar length, after stretching both to the same sample count.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/core/status.h"
#include "processing/synthesis/fragment_fill_options.h"
#include "processing/synthesis/matching_database.h"
#include "processing/synthesis/sketch_signals.h"

namespace mocapfill {

// Sketch frames [first, last] inclusive; consecutive fragments share the boundary frame.
struct SketchFragment {
  int first = 0;
  int last = 0;
  bool rising = false;
};

// One matching candidate: a database fragment and its distance (mean squared difference of
// the normalised driven signals per sample and channel).
struct Candidate {
  int fragment = 0;  // index into MatchingDatabase::fragments()
  float distance = 0.0f;
};

// A channel of the driven set and its weight in the distance.
struct DrivenChannel {
  int channel = 0;
  double weight = 1.0;
};

// How much faster a database fragment moves once stretched onto a sketch fragment's frames:
// its length over the sketch fragment's. With options.stretched_travel, matching (and the
// blend's regression) compares the root's velocities as the stretched take moves them, the
// pace its feet step at in the fill, not as captured: a walk stretched out onto a slow
// sketch's steps otherwise counted as fast as it was captured, and lost to takes that stand.
double StretchSpeedRatio(const DbFragment& db, const SketchFragment& query);

// Cuts the sketch on the band `band` of its densified channel `master_channel`.
Result<std::vector<SketchFragment>> FragmentSketch(const SketchSignals& sketch, int master_channel, int band,
                                                   double rate_hz);

// The keyed channel (joint tangent component) with the most energy in band `band` of the
// densified sketch: the default master channel.
int ChooseMasterChannel(const SketchSignals& sketch, int band, double rate_hz);

// The K best candidates of every sketch fragment, ascending distance; a fragment with no
// admissible database fragment (direction, length ratio) gets the nearest ones regardless of
// direction and length. `sketch_match` is the matching signal of the sketch (frames x
// channels, MatchingSignal of its current values). Work is split over options.threads.
std::vector<std::vector<Candidate>> MatchFragments(const MatchingDatabase& mdb, const Eigen::MatrixXd& sketch_match,
                                                   const std::vector<SketchFragment>& fragments,
                                                   const std::vector<DrivenChannel>& driven,
                                                   const FragmentFillOptions& options);

// MatchFragments with a driver set per fragment: fragment i is matched on sets[set_of[i]].
std::vector<std::vector<Candidate>> MatchFragmentsBySet(const MatchingDatabase& mdb,
                                                        const Eigen::MatrixXd& sketch_match,
                                                        const std::vector<SketchFragment>& fragments,
                                                        const std::vector<std::vector<DrivenChannel>>& sets,
                                                        const std::vector<int>& set_of,
                                                        const FragmentFillOptions& options);

// Matching features scaled so that a squared Euclidean distance between two rows is the
// distance MatchFragments measures: one row per sketch fragment, or per listed database
// fragment (indices into MatchingDatabase::fragments(), rows in that order), its root
// velocities those of the fragment stretched onto `query` (where options.stretched_travel).
Eigen::MatrixXf ScaledSketchFeatures(const MatchingDatabase& mdb, const Eigen::MatrixXd& sketch_match,
                                     const std::vector<SketchFragment>& fragments,
                                     const std::vector<DrivenChannel>& driven, const FragmentFillOptions& options);
Eigen::MatrixXf ScaledDatabaseFeatures(const MatchingDatabase& mdb, const std::vector<DrivenChannel>& driven,
                                       const std::vector<int>& fragments, const SketchFragment& query,
                                       const FragmentFillOptions& options);

// Per sketch fragment: its distance (as MatchFragments measures it) to the database mean
// pose standing still, the all-zero matching signal: how much there is to explain.
std::vector<float> FragmentEnergies(const MatchingDatabase& mdb, const Eigen::MatrixXd& sketch_match,
                                    const std::vector<SketchFragment>& fragments,
                                    const std::vector<DrivenChannel>& driven, const FragmentFillOptions& options);

// For each listed database fragment (indices into MatchingDatabase::fragments()), the
// distance to its nearest admissible fragment of another clip on the driven channels: how
// near the database's own takes come to one another, the yardstick of coverage. Infinity
// where no other clip has an admissible fragment.
std::vector<float> NearestOtherTakeDistances(const MatchingDatabase& mdb,
                                             const std::vector<int>& queries,
                                             const std::vector<DrivenChannel>& driven,
                                             const FragmentFillOptions& options);

}  // namespace mocapfill
