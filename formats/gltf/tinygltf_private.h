// tinygltf for formats/gltf: Debian's tiny_gltf.h compiled into mocapfill_gltf
// (tinygltf_impl.cc) instead of linking libtinygltf.so, under a private namespace name.
//  - Start-up: a shared C++ library pulls libstdc++.so (and libstb) into every process;
//    without it the executable links libstdc++ statically (converter/CMakeLists.txt),
//    and a small conversion starts faster (docs/performance.md).
//  - Symbols: libdraco, which Assimp links, embeds an older tinygltf exporting the same
//    names; a private name can never bind to it, whatever the link order.
// Images are never decoded or encoded (the reader installs a no-op loader), so stb is
// left out. Include only from formats/gltf .cc files.
#pragma once

#include "formats/gltf/tinygltf_name.h"

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#include <tiny_gltf.h>
