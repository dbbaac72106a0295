// glTF 2.0 export: joints as nodes (with a skin over them, and optionally a stick-figure
// mesh, when the scene has no skinned mesh: ExportOptions::gltf_skeleton), one shared time
// accessor per clip, metres, Y-up, provenance in asset.extras, deterministic bytes.
// Validator-clean by construction.
#pragma once

#include <string>
#include <vector>

#include "formats/gltf/gltf_tracks.h"
#include "formats/motion_io.h"

namespace mocapfill {

// Serialises `scene` as .glb (binary = true) or .gltf with an embedded buffer.
Result<std::string> WriteGltf(const Scene& scene, bool binary, const ExportOptions& options);

// A .glb in two pieces that, written one after the other, are the file WriteGltf(binary)
// returns: the glb header, JSON chunk and binary chunk header; then the binary chunk's
// bytes (a multiple of 4; empty when the file has no binary chunk). Kept apart so that a
// large binary chunk is written where it was built, never copied.
struct GlbFile {
  std::string head;
  std::vector<unsigned char> bin;
};
Result<GlbFile> WriteGlb(const Scene& scene, const ExportOptions& options);

// A .glb whose binary chunk starts with one clip's tracks, packed by the caller as
// `layout` says (gltf_tracks.h): the file is head, tracks, then bin (the skin and mesh of
// ExportOptions::gltf_skeleton; empty without them), the bytes WriteGlb writes for the same
// scene and samples. `scene` has a skeleton, no meshes or skins, and one clip whose name,
// rate, frame and joint counts and translation_animated are set; its sample arrays and keys
// are not read (every frame counts as keyed). `first_time_s` / `last_time_s` are the packed
// first and last frame times (the time accessor's min and max).
Result<GlbFile> WriteGlbHeadForTracks(const Scene& scene, const ClipTrackLayout& layout, float first_time_s,
                                      float last_time_s, const ExportOptions& options);

}  // namespace mocapfill
