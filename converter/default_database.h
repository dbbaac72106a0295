// Where the embedded default database lives, and loading a --db argument (an .mfdb file, or
// motion files and folders built into a database in memory).
#pragma once

#include <string>
#include <vector>

#include "processing/core/status.h"
#include "processing/database/motion_database.h"

namespace mocapfill::cli {

// The default database folder: <exe>/../share/mocapfill/default_db when installed, else the
// source tree's fixtures/default_db compiled in. Empty when neither exists.
std::string DefaultDatabaseDir();

// Loads `paths` (empty = the default database): a single .mfdb file is read as is; motion
// files and folders are imported and built. Errors name the path.
Result<MotionDatabase> LoadDatabase(const std::vector<std::string>& paths);

}  // namespace mocapfill::cli
