// Reading, writing and converting motion files: BVH, glTF (.gltf, .glb) and FBX (and the
// other formats Assimp reads) in; glTF and BVH out. Writes are atomic: a file appears
// complete or not at all, and an input is never overwritten.
#pragma once

#include <string>

#include "mocapfill/export.h"
#include "mocapfill/scene.h"

namespace mocapfill::api {

struct LoadOptions {
  std::string unit = "auto";  // length unit of the source: auto, m, cm, mm, in, ft, cmu
  std::string up = "auto";    // up axis of the source: auto, y, z (Z-up is turned to Y-up)
  double rate_hz = 0.0;       // sampling rate for keyed sources (glTF, FBX); 0 = from the key times
  std::string animation;      // which animation, by name or index; "" = every one
  bool strict = false;        // recoverable oddities are errors
};

struct SaveOptions {
  std::string unit = "auto";  // BVH length unit; auto = the source's
  bool pretty = true;         // .gltf: indented JSON
  // glTF: "skin" (a skin over the joints, so importers make an armature), "mesh" (also a
  // skinned stick figure) or "nodes" (bare joint nodes).
  std::string gltf_skeleton = "skin";
  // BVH: "source" (the source's channel layout, exact) or "standard" (rotation channels on
  // every joint, position channels only where joints translate: what every reader reads).
  std::string bvh_layout = "source";
};

// Throws Error: kInvalidInput naming the file and the line or field, kUsage for bad options.
MOCAPFILL_API Scene Load(const std::string& path, const LoadOptions& options = {});
// Writes .gltf, .glb or .bvh by the extension. Throws Error (kOutput) when it cannot.
MOCAPFILL_API void Save(const Scene& scene, const std::string& path, const SaveOptions& options = {});
// Load then Save in one step (BVH to .glb is streamed). Refuses to overwrite the input.
MOCAPFILL_API void Convert(const std::string& input, const std::string& output, const LoadOptions& load = {},
                           const SaveOptions& save = {});

}  // namespace mocapfill::api
