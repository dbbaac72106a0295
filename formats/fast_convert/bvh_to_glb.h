// BVH to .glb without the double-precision clip in between. The MOTION rows are parsed
// straight into the .glb's float32 tracks (bvh_track_rows.h) and the JSON comes from the
// glTF writer (WriteGlbHeadForTracks), so the file is byte for byte the one ReadBvh and
// WriteGlb make, with a fifth of the memory and without the passes over the clip between
// them (the double-precision clip, its freshly faulted pages, and the validation, scaling
// and keying passes).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "formats/fast_convert/large_buffer.h"
#include "formats/motion_io.h"

namespace mocapfill::fast_convert {

struct StreamedGlb {
  std::string head;    // glb header, JSON chunk, binary chunk header
  LargeBuffer tracks;  // the binary chunk's start: the clip's tracks
  std::vector<unsigned char> tail;  // the rest of the binary chunk: the skin (ExportOptions::gltf_skeleton)
};

// The .glb of BVH `text` (`path` names it in the file's provenance), when the conversion
// is a plain one: valid text whose import gives no warning, a Y-up source, and a clip
// whose frame times fit float32. nullopt otherwise; ImportFile and ExportFile then give the
// same file, or the error or warning, through the clip.
// `threads` as ConvertOptions::threads.
std::optional<StreamedGlb> StreamBvhToGlb(std::string_view text, const std::string& path, const ImportOptions& options,
                                          const ExportOptions& export_options = {}, int threads = 0);

}  // namespace mocapfill::fast_convert
