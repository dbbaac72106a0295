// Matching a sketch's skeleton to the database's by joint name (issue #4): the sketch may come
// from another tool (other joint names: a user map renames them), carry extra joints (kept as
// they are), or lack database joints (those are missing and get synthesised).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"

namespace mocapfill {

struct SkeletonMapping {
  std::vector<int> db_to_sketch;  // per database joint: the sketch joint, or -1 (missing)
  std::vector<int> sketch_to_db;  // per sketch joint: the database joint, or -1 (not in the database)
  std::vector<std::string> warnings;
};

// Maps joints by name after renaming sketch names through `rename` (sketch -> database).
// Errors (kInvalidData), each naming joints and suggesting --map: no sketch joint is in the
// database; a keyed sketch joint is not in the database; a mapped joint whose database parent
// maps to a sketch joint that is not its ancestor (mismatched hierarchy).
Result<SkeletonMapping> MapSkeletons(const Skeleton& sketch, const MotionClip& sketch_clip, const Skeleton& database,
                                     const std::map<std::string, std::string>& rename);

// The sketch clip in database joint order: mapped joints carry the sketch's rotations and keys;
// missing joints hold the database rest pose and no keys. Translations of the motion root come
// from the sketch; other joints keep the database rest offsets.
MotionClip ToDatabaseClip(const SkeletonMapping& mapping, const Skeleton& database, const MotionClip& sketch_clip);

// The filled clip back on the sketch's skeleton: mapped joints take the filled rotations (and
// the motion root its translation); sketch joints unknown to the database keep their sketch
// values. Every joint is keyed at every frame.
MotionClip ToSketchClip(const SkeletonMapping& mapping, const MotionClip& filled, const MotionClip& sketch_clip,
                        int database_root_joint);

}  // namespace mocapfill
