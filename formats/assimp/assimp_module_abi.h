// The boundary between mocapfill and its Assimp plug-in (mocapfill_assimp.so).
// libassimp is large: mapping and relocating it costs every process milliseconds of
// start-up even when it reads a BVH. So the Assimp reader is built as a module that
// ImportFile dlopen()s only for Assimp extensions (assimp_loader.cc), and BVH/glTF
// conversions never load it. Both sides are built from the same sources in the same
// build; the ABI key rejects a stale module from another build or version.
#pragma once

#include <cstdint>
#include <string>

#include "formats/motion_io.h"

namespace mocapfill::assimp_module {

// File name of the module, looked for beside the executable, in <prefix>/lib/mocapfill/
// and at its build-tree path.
inline constexpr const char* kFileName = "mocapfill_assimp.so";

// Exported symbols (C linkage, so dlsym finds them by these plain names).
inline constexpr const char* kAbiSymbol = "mocapfill_assimp_module_abi";
inline constexpr const char* kReadSymbol = "mocapfill_assimp_module_read";

// Changes whenever the types that cross the boundary change shape.
inline constexpr uint64_t kAbiKey = (uint64_t{1} << 48) ^ (uint64_t{sizeof(Scene)} << 32) ^
                                    (uint64_t{sizeof(ImportOptions)} << 16) ^ uint64_t{sizeof(MotionClip)} ^
                                    (uint64_t{sizeof(Skeleton)} << 8) ^ (uint64_t{sizeof(Status)} << 24);

using AbiFunction = uint64_t (*)();
// Reads `*path` with Assimp into `*out` (ReadWithAssimp's result).
using ReadFunction = void (*)(const std::string* path, const ImportOptions* options, Result<Scene>* out);

}  // namespace mocapfill::assimp_module
