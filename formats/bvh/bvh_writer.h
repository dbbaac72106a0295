// BVH export: writes each joint's channels in the layout the source had (or 6 channels
// on roots and 3 elsewhere, ZXY, for non-BVH sources), or in the standard layout
// (ExportOptions::bvh_layout), Euler angles continuous over time.
#pragma once

#include <string>

#include "formats/motion_io.h"

namespace mocapfill {

// Serialises the first clip of `scene` as BVH text.
Result<std::string> WriteBvh(const Scene& scene, const ExportOptions& options);

}  // namespace mocapfill
