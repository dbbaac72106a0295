// glTF 2.0 export: joints as nodes, one shared time accessor per clip, metres, Y-up,
// provenance in asset.extras, deterministic bytes. Validator-clean by construction.
#pragma once

#include <string>

#include "formats/motion_io.h"

namespace mocapfill {

// Serialises `scene` as .glb (binary = true) or .gltf with an embedded buffer.
Result<std::string> WriteGltf(const Scene& scene, bool binary, const ExportOptions& options);

}  // namespace mocapfill
