// ImportFile's way to the Assimp reader: loads mocapfill_assimp.so on first use (see
// assimp_module_abi.h for why it is a module) and forwards to ReadWithAssimp there.
#pragma once

#include <string>

#include "formats/motion_io.h"

namespace mocapfill {

// ReadWithAssimp through the module. kUnsupported, naming every place looked in, when the
// module is missing, cannot be loaded, or comes from another build.
Result<Scene> ReadWithAssimpModule(const std::string& path, const ImportOptions& options);

}  // namespace mocapfill
