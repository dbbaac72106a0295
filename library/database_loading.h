// Loading a motion database, shared by the CLI's verbs, the pipeline's database node and the
// public API: a built .mfdb file (read and verified), motion files and folders imported in
// parallel and built in memory (nothing is written that the caller did not ask for), or the
// default database that ships with mocapfill.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "formats/motion_io.h"
#include "processing/core/motion_database.h"
#include "processing/core/status.h"
#include "processing/database/motion_database_builder.h"

namespace mocapfill {

// How a database is built from motion files.
struct DatabaseBuildOptions {
  double rate_hz = 30.0;   // working rate (Hz)
  // Joint-name map: inline JSON {"source joint": "database joint", ...} or a JSON file; empty = none.
  std::string map;
  int threads = 0;         // import and build threads (0 = all cores)
  // Add each clip's left/right mirror image (DatabaseOptions::mirror).
  bool mirror = DatabaseOptions{}.mirror;
  ImportOptions import;
};

// Called after each imported file with the files done and the total (from worker threads);
// may be empty. No default: the CLI wraps these two loaders with its progress bar under the
// same names, and a defaulted argument would make its two-argument calls ambiguous.
using ImportProgress = std::function<void(size_t done, size_t total)>;


// Imports every motion file under `paths` and builds a database. Clips of another rig than
// the first file's are retargeted onto it. Errors carry the failing file's path.
Result<MotionDatabase> BuildDatabaseFromPaths(const std::vector<std::string>& paths, const DatabaseBuildOptions& options,
                                              const ImportProgress& progress);

// True when `path` names an .mfdb file (by extension or by its magic bytes).
bool IsDatabaseFile(const std::string& path);

// The default database folder: <prefix>/share/mocapfill/default_db beside the installed
// executable or library that holds this code, else the source tree's fixtures/default_db.
// Empty when neither exists.
std::string DefaultDatabaseDir();

// The one database loader. `paths` empty (or the single word "default") = the default
// database; a single .mfdb file is read as is; motion files and folders are imported and
// built with `options`. Errors name the path.
Result<MotionDatabase> LoadDatabase(const std::vector<std::string>& paths, const DatabaseBuildOptions& options,
                                    const ImportProgress& progress);

}  // namespace mocapfill
