// Command-line flags shared by every verb that reads motion files.
#pragma once

#include <CLI/CLI.hpp>

#include "formats/motion_io.h"

namespace mocapfill::cli {

// Adds --unit, --up, --rate, --animation and --strict bound to `options`.
void AddImportFlags(CLI::App& command, ImportOptions& options);

}  // namespace mocapfill::cli
