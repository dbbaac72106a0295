// The embedded default database (fixtures/default_db), built once per test program.
#pragma once

#include "processing/core/motion_clip.h"
#include "processing/core/motion_database.h"

namespace mocapfill::testing {

const MotionDatabase& DefaultDb();

// The shipped sketch (fixtures/sketches/walk_proud_002_legs8.glb: hips and legs keyed every 8
// frames, on the database's own rig) as a clip on the default database's skeleton, keys kept:
// the input of the fill methods below FillSketch.
MotionClip ShippedSketchOnDefaultDbRig();

}  // namespace mocapfill::testing
