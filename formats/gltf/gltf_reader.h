// glTF 2.0 import (.gltf and .glb through tinygltf): node hierarchy, skins and meshes,
// LINEAR/STEP/CUBICSPLINE samplers, several animations; key times are preserved as keyed frames.
#pragma once

#include <string>

#include "formats/motion_io.h"

namespace mocapfill {

// `bytes` is the file content; `path` labels messages and resolves relative buffer URIs.
Result<Scene> ReadGltf(const std::string& bytes, const std::string& path, const ImportOptions& options);

}  // namespace mocapfill
