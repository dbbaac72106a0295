// glTF 2.0 export: joints as nodes, one shared time accessor per clip, metres, Y-up,
// provenance in asset.extras, deterministic bytes. Validator-clean by construction.
#pragma once

#include <string>
#include <vector>

#include "formats/motion_io.h"

namespace mocapfill {

// Serialises `scene` as .glb (binary = true) or .gltf with an embedded buffer.
Result<std::string> WriteGltf(const Scene& scene, bool binary, const ExportOptions& options);

// A .glb in two pieces that, written one after the other, are the file WriteGltf(binary)
// returns: the glb header, JSON chunk and binary chunk header; then the binary chunk's
// bytes (a multiple of 4; empty when the file has no binary chunk). Kept apart so that a
// large binary chunk is written where it was built, never copied.
struct GlbFile {
  std::string head;
  std::vector<unsigned char> bin;
};
Result<GlbFile> WriteGlb(const Scene& scene, const ExportOptions& options);

}  // namespace mocapfill
