// Loading a motion database, shared by every verb that uses one and by the pipeline's
// database node: a built .mfdb file (read and verified), motion files/folders imported in
// parallel and built in memory on the fly (nothing is written that the user did not ask
// for), or the embedded default database.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "formats/motion_io.h"
#include "processing/core/status.h"
#include "processing/database/motion_database.h"

namespace mocapfill::cli {

// How a database is built from motion files.
struct DatabaseBuildFlags {
  double rate_hz = 30.0;   // working rate (Hz)
  std::string map_path;    // JSON object {"source joint": "database joint", ...}; empty = none
  int threads = 0;         // import and build threads (0 = all cores)
  ImportOptions import;
};

// Adds --rate, --map, --threads, --unit and --up bound to `flags`.
void AddDatabaseBuildFlags(CLI::App& command, DatabaseBuildFlags& flags);

// Parses joint-name map JSON; errors start with `origin` (kInvalidData for bad JSON or
// non-string values).
Result<std::map<std::string, std::string>> ParseJointNameMap(const std::string& text, const std::string& origin);

// Reads a joint-name map file. Errors name the file (kInvalidData for bad JSON or non-string
// values, kIoError when unreadable).
Result<std::map<std::string, std::string>> ReadJointNameMap(const std::string& path);

// Imports every motion file under `paths` (progress bar on a terminal) and builds a database.
// Errors carry the failing file's path.
Result<MotionDatabase> BuildDatabaseFromPaths(const std::vector<std::string>& paths, const DatabaseBuildFlags& flags);

// True when `path` names an .mfdb file (by extension or by its magic bytes).
bool IsDatabaseFile(const std::string& path);

// The default database folder: <exe>/../share/mocapfill/default_db when installed, else the
// source tree's fixtures/default_db compiled in. Empty when neither exists.
std::string DefaultDatabaseDir();

// The one database loader. `paths` empty = the default database; a single .mfdb file is read
// as is; motion files and folders are imported and built with `flags`. Errors name the path.
Result<MotionDatabase> LoadDatabase(const std::vector<std::string>& paths, const DatabaseBuildFlags& flags = {});

// A --db value: LoadDatabase({path}, flags).
Result<MotionDatabase> LoadDatabaseArg(const std::string& path, const DatabaseBuildFlags& flags = {});

}  // namespace mocapfill::cli
