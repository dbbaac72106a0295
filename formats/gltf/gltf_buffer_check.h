// Checks a glTF document's buffers before tinygltf loads them: tinygltf's own messages
// for a short data URI or a missing .bin do not say which buffer or by how much.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "processing/core/status.h"

namespace mocapfill::gltf_internal {

// `json_text` is the glTF JSON; `base_dir` resolves relative buffer URIs; `glb_bin_bytes`
// is the size of the GLB BIN chunk (nullopt for .gltf or a GLB without one). Fails with
// kInvalidData naming the field, e.g. "buffers[0]: byteLength 4096 but the data URI holds 640 bytes".
Status CheckBuffers(std::string_view json_text, const std::string& base_dir, std::optional<size_t> glb_bin_bytes);

}  // namespace mocapfill::gltf_internal
