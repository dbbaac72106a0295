// BVH (Biovision hierarchy) import: any rotation order and channel layout per joint,
// several roots, End Sites, names with spaces, any line ending; errors carry line:column.
#pragma once

#include <string>
#include <string_view>

#include "formats/motion_io.h"

namespace mocapfill {

// Parses BVH text. `path` only labels messages. Units and axes are resolved per `options`.
Result<Scene> ReadBvh(std::string_view text, const std::string& path, const ImportOptions& options);

}  // namespace mocapfill
