// The fill stage (issue #4): completes a sketch (keyed joints plus missing ones) from a motion
// database with one of the methods of FillOptions, and reports where everything came from.
// The sketch must already be in the database's joint order and rate (skeleton_map.h and
// motion/resample.h bring it there).
#pragma once

#include <memory>

#include "processing/core/motion_clip.h"
#include "processing/database/motion_database.h"
#include "processing/synthesis/fill_options.h"

namespace mocapfill {

class MatchingDatabase;

struct FillResult {
  MotionClip clip;   // database joint order and rate, every joint keyed at every frame
  FillReport report;
};

// Holds the database and caches its sketch-filtered copy between fills of sketches with the
// same keyed channels and key spacing (an evaluation fills many such sketches). Not
// thread-safe: one engine per thread; matching inside a fill uses options.threads.
class FillEngine {
 public:
  explicit FillEngine(const MotionDatabase& db);
  ~FillEngine();
  FillEngine(const FillEngine&) = delete;
  FillEngine& operator=(const FillEngine&) = delete;

  // Fills every joint the sketch does not key. Keyed joints keep the sketch's rotations
  // (textured with the matched high bands when options.texture, keys re-pinned). Errors:
  // invalid options (kInvalidArgument); a sketch that does not fit the database skeleton,
  // has no frames or no keyed joint (kInvalidData).
  Result<FillResult> Fill(const MotionClip& sketch, const FillOptions& options);

 private:
  const MotionDatabase& db_;
  std::unique_ptr<MatchingDatabase> cache_;
};

}  // namespace mocapfill
