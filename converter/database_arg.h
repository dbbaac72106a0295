// The CLI's side of loading a motion database (library/database_loading.h): the flags that
// say how to build one, and a progress bar while files are imported.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "library/database_loading.h"

namespace mocapfill::cli {

using DatabaseBuildFlags = DatabaseBuildOptions;
using mocapfill::DefaultDatabaseDir;
using mocapfill::IsDatabaseFile;

// Adds --rate, --map, --threads, --unit, --up and --mirror bound to `flags`.
void AddDatabaseBuildFlags(CLI::App& command, DatabaseBuildFlags& flags);

// Adds `--mirror on|off` bound to `mirror` (DatabaseOptions::mirror), for verbs that build
// databases of their own (eval's folds).
void AddMirrorFlag(CLI::App& command, bool& mirror);

// mocapfill::BuildDatabaseFromPaths with a progress bar on a terminal.
Result<MotionDatabase> BuildDatabaseFromPaths(const std::vector<std::string>& paths, const DatabaseBuildFlags& flags);

// mocapfill::LoadDatabase with a progress bar on a terminal: `paths` empty or "default" =
// the default database.
Result<MotionDatabase> LoadDatabase(const std::vector<std::string>& paths, const DatabaseBuildFlags& flags = {});

// A --db value: LoadDatabase({path}, flags).
Result<MotionDatabase> LoadDatabaseArg(const std::string& path, const DatabaseBuildFlags& flags = {});

}  // namespace mocapfill::cli
