// The embedded default database (fixtures/default_db), built once per test program.
#pragma once

#include <string>

#include "processing/core/motion_clip.h"
#include "processing/core/motion_database.h"

namespace mocapfill::testing {

const MotionDatabase& DefaultDb();

// The shipped sketch (fixtures/sketches/walk_proud_002_legs8.glb: hips and legs keyed every 8
// frames, on the database's own rig) as a clip on the default database's skeleton, keys kept:
// the input of the fill methods below FillSketch.
MotionClip ShippedSketchOnDefaultDbRig();

// The shared corpus's Bandai-Namco database without the clips of one style, as a fold of
// leave-one-style-out sees it (built once per style and test program).
const MotionDatabase& BandaiDbWithout(const std::string& style);

}  // namespace mocapfill::testing
