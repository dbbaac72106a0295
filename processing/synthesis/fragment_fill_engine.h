// The fragment methods and the baselines as one fill (thesis chapter 4):
// completes a sketch (keyed joints plus missing ones) from a motion database with `mean`,
// `nn`, `fragment` or `hierarchical`, and reports where everything came from. The sketch must
// already be on the database's rig and at its rate (sketch_fill/ brings a sketch on any rig
// there). FillEngine (processing/fill) runs these and the PCA-based methods by name.
#pragma once

#include <Eigen/Core>
#include <map>
#include <memory>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/status.h"
#include "processing/core/motion_database.h"
#include "processing/synthesis/fragment_fill_options.h"
#include "processing/synthesis/fragment_fill_report.h"
#include "processing/synthesis/limb_reach.h"

namespace mocapfill {

class MatchingDatabase;
struct DatabaseContacts;

// Per upper-body joint group (its joints), the positions its rotations give the joints it
// places in every database frame (consensus_weights.h: GroupPositions).
using GroupPositionCache = std::map<std::vector<int>, Eigen::MatrixXf>;

// The coverage yardstick of a matching database (coverage.h: ReferenceDistance), the driven
// channels and the options it was measured with; distance < 0 until measured.
struct CoverageYardstick {
  double distance = -1.0;
  std::vector<int> channels;
  double root_feature_weight = 0.0, min_length_ratio = 0.0, max_length_ratio = 0.0;
  bool stretched_travel = false;
  int reference_fragments = 0;

  bool Serves(const std::vector<int>& driven_channels, const FragmentFillOptions& o) const {
    return distance >= 0.0 && channels == driven_channels && root_feature_weight == o.root_feature_weight &&
           min_length_ratio == o.min_length_ratio && max_length_ratio == o.max_length_ratio &&
           stretched_travel == o.stretched_travel && reference_fragments == o.coverage.reference_fragments;
  }
};

// Holds the database and caches its sketch-filtered copy between fills of sketches with the
// same keyed channels and key spacing (an evaluation fills many such sketches). Not
// thread-safe: one engine per thread; matching inside a fill uses options.threads.
class FragmentFillEngine {
 public:
  explicit FragmentFillEngine(const MotionDatabase& db);
  ~FragmentFillEngine();
  FragmentFillEngine(const FragmentFillEngine&) = delete;
  FragmentFillEngine& operator=(const FragmentFillEngine&) = delete;

  const MotionDatabase& db() const { return db_; }

  // Fills every joint the sketch does not key (database joint order and rate, every joint
  // keyed at every frame) and writes `report`. Keyed joints keep the sketch's rotations
  // (textured with the matched high bands when options.texture, keys re-pinned). Errors:
  // invalid options, a PCA-based method (kInvalidArgument); a sketch that does not fit the
  // database skeleton, has no frames or no keyed joint (kInvalidData).
  Result<MotionClip> Fill(const MotionClip& sketch, const FragmentFillOptions& options, FragmentFillReport& report);

 private:
  const MotionDatabase& db_;
  std::unique_ptr<MatchingDatabase> cache_;
  CoverageYardstick yardstick_;  // of cache_
  std::unique_ptr<DatabaseContacts> contacts_;  // the takes' foot contacts, found on first need
  std::unique_ptr<ArmReach> arm_reach_;         // the rig's arms (limb_reach.h), found on first need
  GroupPositionCache group_positions_;          // per upper-body group (consensus_weights.h), on first need
  Eigen::VectorXd db_sway_;                     // per database frame, LateralSway (gait_sway.h), on first need
};

}  // namespace mocapfill
