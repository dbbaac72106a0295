// A stored clip of the motion database back in signal space and as motion: the inverse of
// what MotionDatabaseBuilder stores per clip (an algorithm, so not a method of the core type).
#pragma once

#include "processing/core/motion_clip.h"
#include "processing/core/motion_database.h"
#include "processing/core/status.h"
#include "processing/motion/tangent_space.h"

namespace mocapfill {

// One clip in signal space (double precision copy of its rows).
ClipSignals ClipSignalsOf(const MotionDatabase& database, int clip_index);

// One clip as a MotionClip at the database's rate (rotations from the tangent coordinates,
// root re-integrated from the features, other animated translations from storage), all
// frames keyed. Equal to the clip given to the builder up to float32 storage rounding.
// An index outside the database: kInvalidArgument.
Result<MotionClip> ReconstructClip(const MotionDatabase& database, int clip_index);

}  // namespace mocapfill
