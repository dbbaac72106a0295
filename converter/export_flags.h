// Command-line flags shared by every verb that writes motion files.
#pragma once

#include <CLI/CLI.hpp>

#include "formats/motion_io.h"

namespace mocapfill::cli {

// Adds --no-skin, --skeleton-mesh (glTF) and --bvh-layout (BVH) bound to `options`.
void AddExportFlags(CLI::App& command, ExportOptions& options);

}  // namespace mocapfill::cli
