// For tests of the glTF writer: a check of its JSON that does not depend on how the text is
// laid out. tinygltf stays out of this header, so tests that use another tinygltf can
// include it.
#pragma once

#include "formats/motion_io.h"
#include "processing/core/scene.h"
#include "processing/core/status.h"

namespace mocapfill::gltf_internal {

// Writes `scene` as WriteGltf does (.glb when `binary`, else .gltf), reads the bytes back
// with tinygltf's loader and compares the model read with the model the exporter built,
// member by member: OK when they are the same, else a message naming the first member that
// differs ("nodes[3]") or the loader's error.
Status CheckWrittenModelReadsBack(const Scene& scene, bool binary, const ExportOptions& options = {});

}  // namespace mocapfill::gltf_internal
