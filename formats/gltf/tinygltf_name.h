// The name our private copy of tinygltf lives under (see tinygltf_private.h). Included by
// the internal headers before they forward-declare tinygltf types, so that every mention
// of tinygltf:: in formats/gltf means the copy compiled into mocapfill_gltf.
#pragma once

#define tinygltf mocapfill_tinygltf
