// Building the motion database (processing/core/motion_database.h) from clips: resampling
// to one working rate, the joint means, the signal-space decomposition, the band-pass levels
// and the joint-correlation table. Loading a built one from disk is formats/mfdb's.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/motion_database.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"

namespace mocapfill {

struct DatabaseOptions {
  double rate_hz = 30.0;  // working rate every clip is resampled to (slerp rotations, cubic root)
  // Bands kept in float32, chosen by frequency (nearest peak): at 30 Hz {2, 1, 0.5} Hz are
  // L2 (step), L3 (stride: default fragmentation/matching band) and L4. Other bands are
  // cheap to recompute per clip with BuildPyramid on ClipSignalRows().
  std::vector<double> stored_band_hz = {2.0, 1.0, 0.5};
  double correlation_band_hz = 1.0;    // band of the correlation table (nearest peak; L3 at 30 Hz)
  double correlation_max_lag_s = 0.25;  // lags searched: |tau| <= round(this * rate_hz) frames
  int threads = 0;                      // worker threads for Build (0 = hardware concurrency)
  // Adds each clip's left/right mirror image (processing/motion/mirror.h) as another clip,
  // named "<clip>#mirror" with the clip's labels: twice the takes to match, each turn and
  // one-sided gesture in both directions. Needs a humanoid rig (sides from its mapping).
  bool mirror = false;

  // Fails with kInvalidArgument naming the field.
  Status Validate() const;
};

// Collects clips, then computes the database in Build().
class MotionDatabaseBuilder {
 public:
  explicit MotionDatabaseBuilder(DatabaseOptions options = {});

  // Renames joints of added clips before matching them against the database skeleton:
  // source joint name -> database joint name. Names not in the map are kept.
  void SetJointNameMap(std::map<std::string, std::string> source_to_database);

  // Adds one clip. The first clip's skeleton (after renaming) becomes the database's. A later
  // clip must have the same joints with the same parents, in any order (it is re-ordered);
  // otherwise kInvalidData naming the clip and the first differing joint, e.g.
  // "clip 'x': joint 'Hand_L' is missing (database skeleton has it)". Rest offsets may differ
  // (the database keeps the first skeleton's). The clip is validated and resampled to
  // options.rate_hz here. `labels` may be empty; labels["file"] is conventionally the path.
  Status Add(const Skeleton& skeleton, MotionClip clip, ClipLabels labels);

  int num_clips() const { return static_cast<int>(clips_.size()); }

  // Computes means, signals, stored bands and the correlation table (after the mirrored
  // clips, when options.mirror, each added after all the captured ones). Deterministic: the
  // same clips added in the same order give identical databases, whatever the thread count.
  // Errors: no clips (kInvalidArgument), invalid options, a rig mirroring cannot tell the
  // sides of (kInvalidData).
  Result<MotionDatabase> Build() const;

 private:
  DatabaseOptions options_;
  std::map<std::string, std::string> name_map_;
  std::optional<Skeleton> skeleton_;
  std::vector<MotionClip> clips_;
  std::vector<ClipLabels> labels_;
};

}  // namespace mocapfill
