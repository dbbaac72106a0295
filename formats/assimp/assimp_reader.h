// FBX (and other Assimp formats) import: pivots and pre-rotations folded into joints,
// unit scale applied, no $AssimpFbx$ helper nodes, skin weights renormalised.
#pragma once

#include <string>

#include "formats/motion_io.h"

namespace mocapfill {

Result<Scene> ReadWithAssimp(const std::string& path, const ImportOptions& options);

}  // namespace mocapfill
