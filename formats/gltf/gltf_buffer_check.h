// Checks a glTF document before tinygltf loads it: its size in JSON values (tinygltf holds
// about 1.1 KB per accessor while it loads, so ten million of them would take gigabytes),
// and its buffers (tinygltf's own messages for a short data URI or a missing .bin do not say
// which buffer or by how much).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "processing/core/status.h"

namespace mocapfill::gltf_internal {

// The most JSON objects and values a glTF document may hold: a million objects (accessors,
// nodes, ...) load in about 1.1 GB; real scenes have thousands.
constexpr size_t kMaxGltfJsonObjects = 1'000'000;
constexpr size_t kMaxGltfJsonValues = 10'000'000;

// Counts objects and values in one pass over the text (no parse) and refuses a document
// beyond the limits above with kInvalidData saying how many it holds.
Status CheckJsonSize(std::string_view json_text);

// `json_text` is the glTF JSON; `base_dir` resolves relative buffer URIs; `glb_bin_bytes`
// is the size of the GLB BIN chunk (nullopt for .gltf or a GLB without one). Fails with
// kInvalidData naming the field, e.g. "buffers[0]: byteLength 4096 but the data URI holds 640 bytes".
Status CheckBuffers(std::string_view json_text, const std::string& base_dir, std::optional<size_t> glb_bin_bytes);

}  // namespace mocapfill::gltf_internal
