// The embedded default database (fixtures/default_db), built once per test program.
#pragma once

#include "processing/database/motion_database.h"

namespace mocapfill::testing {

const MotionDatabase& DefaultDb();

}  // namespace mocapfill::testing
