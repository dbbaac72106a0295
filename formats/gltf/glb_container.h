// The GLB container (binary glTF): a 12-byte header, a JSON chunk and an optional BIN
// chunk. Checked here before tinygltf sees the bytes, so that truncated or foreign files
// are rejected with a message that says which part is wrong and by how much.
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

#include "processing/core/status.h"

namespace mocapfill::gltf_internal {

struct GlbParts {
  std::string_view json;                 // the JSON chunk's text
  std::optional<size_t> bin_size_bytes;  // BIN chunk payload size, when there is one
};

// True when `bytes` starts with the GLB magic "glTF".
bool HasGlbMagic(std::string_view bytes);

// Splits a GLB file into its chunks, checking the header, chunk types and lengths.
// Errors are kInvalidData, e.g. "GLB header: declared length 5000 bytes but the file has 2500".
Result<GlbParts> ParseGlbContainer(std::string_view bytes);

}  // namespace mocapfill::gltf_internal
