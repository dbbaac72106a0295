// The --db argument shared by every verb that uses a motion database: either a built .mfdb
// file (read and verified) or motion files/folders, imported in parallel and built in memory
// on the fly (nothing is written that the user did not ask for).
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

// Reads a joint-name map file. Errors name the file (kInvalidData for bad JSON or non-string
// values, kIoError when unreadable).
Result<std::map<std::string, std::string>> ReadJointNameMap(const std::string& path);

// Imports every motion file under `paths` (progress bar on a terminal) and builds a database.
// Errors carry the failing file's path.
Result<MotionDatabase> BuildDatabaseFromPaths(const std::vector<std::string>& paths, const DatabaseBuildFlags& flags);

// True when `path` names an .mfdb file (by extension or by its magic bytes).
bool IsDatabaseFile(const std::string& path);

// A --db value: an .mfdb file is read; a folder or motion file is built in memory.
Result<MotionDatabase> LoadDatabaseArg(const std::string& path, const DatabaseBuildFlags& flags = {});

}  // namespace mocapfill::cli
