// The one translation unit holding tinygltf's implementation (see tinygltf_private.h), and
// GlbJson, which needs tinygltf's file-local serialisers.
#define TINYGLTF_IMPLEMENTATION
#include "formats/gltf/tinygltf_private.h"

#include "formats/gltf/gltf_export_internal.h"

namespace mocapfill::gltf_internal {

// TinyGLTF::WriteGltfSceneToStream for a binary file, step for step (tiny_gltf.h 2.7), up
// to the JSON text, with buffers[0]'s byteLength taken from `bin_bytes`: the bytes written
// are the same, but the binary chunk stays with the caller instead of being copied into the
// model, then the JSON writer's copy, then a string stream and its string.
std::string GlbJson(const tinygltf::Model& model, size_t bin_bytes) {
  if (std::optional<std::string> json = SkeletonGlbJson(model, bin_bytes)) return std::move(*json);
  return TinygltfGlbJson(model, bin_bytes);
}

std::string TinygltfGlbJson(const tinygltf::Model& model, size_t bin_bytes) {
  ::JsonDocument output;
  tinygltf::SerializeGltfModel(&model, output);
  if (bin_bytes > 0) {
    ::json buffers;
    tinygltf::JsonReserveArray(buffers, 1);
    ::json buffer;
    tinygltf::SerializeNumberProperty("byteLength", bin_bytes, buffer);
    tinygltf::JsonPushBack(buffers, std::move(buffer));
    tinygltf::JsonAddMember(output, "buffers", std::move(buffers));
  }
  return tinygltf::JsonToString(output);
}

}  // namespace mocapfill::gltf_internal
