// Internal to formats/gltf: pieces of the writer shared between its .cc files. tinygltf
// stays out of headers; the model is only forward-declared here (under its private name).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "formats/gltf/gltf_generated.h"
#include "formats/gltf/gltf_str.h"
#include "formats/gltf/tinygltf_name.h"
#include "formats/motion_io.h"
#include "processing/core/scene.h"
#include "processing/core/status.h"

namespace tinygltf {
class Model;
}

namespace mocapfill::gltf_internal {

// The single binary buffer of an exported file, with the buffer views and accessors over
// it. Views start on 4-byte boundaries with zero padding between them, and carry no
// byteStride (every view is tightly packed), so the bytes are the same on every run.
class BufferWriter {
 public:
  explicit BufferWriter(tinygltf::Model& model) : model_(model) {}

  // Room for `bytes` more bytes, so that large animations are not copied while they grow.
  void Reserve(size_t bytes);

  // Appends `size` bytes as a new buffer view; `target` is 0 (animation, skin data),
  // 34962 (vertex attributes) or 34963 (indices). Returns the view index.
  int AddView(const void* data, size_t size, int target = 0);

  // Appends a view of `count` floats for the caller to fill in place (no staging copy);
  // the pointer is valid until the next Add*. Sets `view` to the view index.
  float* AddFloatView(size_t count, int& view);

  // Adds a view over bytes the caller keeps apart (a .glb's binary chunk packed elsewhere);
  // only for a writer that holds no bytes itself. Returns the view index.
  int AddViewAt(size_t byte_offset, size_t byte_length);

  // Adds an accessor over `view` at `byte_offset`; min/max only when given.
  int AddAccessor(int view, size_t byte_offset, int component_type, int type, size_t count,
                  const std::vector<double>& min = {}, const std::vector<double>& max = {});

  // Pads the bytes to a multiple of 4 and stores them as buffers[0] (if any were added).
  void Finish();

  // For .glb: pads the bytes to a multiple of 4 and hands them over (the binary chunk);
  // the model gets no buffer entry (GlbJson writes it).
  std::vector<unsigned char> TakeBinaryChunk();

  // The views added from here on follow `bytes` bytes (a multiple of 4) that the caller
  // keeps apart at the start of the binary chunk (AddViewAt's); TakeBinaryChunk then
  // returns what comes after them.
  void StartAfter(size_t bytes) { base_ = bytes; }

 private:
  tinygltf::Model& model_;
  std::vector<unsigned char> bytes_;
  size_t base_ = 0;
};

// Adds the scene's meshes, their materials and the skins they use. Joint j must already be
// node j. Skinned-mesh nodes go to the scene root with an identity transform (the
// validator warns about anything else); rigid meshes become children of their joint's
// node. Root-level mesh nodes are appended to `scene_roots`.
Status ExportMeshes(const Scene& scene, BufferWriter& buffer, tinygltf::Model& model, std::vector<int>& scene_roots);

// One skin (its inverse bind matrices, skeleton = the joints' common root) into the model;
// returns its index.
Result<int> ExportSkin(const Skin& skin, const Skeleton& skeleton, BufferWriter& buffer, tinygltf::Model& model);

// One mesh (primitives, materials) and a node for it, without a skin (the caller sets the
// node's skin); returns the node's index. The caller places the node in the scene.
Result<int> ExportMesh(const Mesh& mesh, const std::vector<Skin>& skins, const Skeleton& skeleton, BufferWriter& buffer,
                       tinygltf::Model& model);

// The skin and stick-figure mesh written for a scene without a skinned mesh of its own
// (ExportOptions::gltf_skeleton), named kGeneratedSkeletonName (gltf_generated.h) and
// recorded in asset.extras.mocapfill.generated_skeleton.
bool NeedsGeneratedSkeleton(const Scene& scene, GltfSkeleton option);
// Every joint (joint j = skin slot j), bound in the rest pose: inverse bind matrix j is the
// inverse of joint j's world rest transform.
Skin RestPoseSkin(const Skeleton& skeleton);
// An octahedron per bone (parent to child, and joint to End Site) in the rest pose, every
// vertex bound fully to the bone's parent joint; skin 0 (RestPoseSkin).
Mesh StickFigureMesh(const Skeleton& skeleton);
struct GeneratedSkeleton {
  int skin = -1;
  int mesh = -1;       // -1 without the mesh
  int mesh_node = -1;  // at the scene root, untransformed (a skinned mesh's node must be)
};
Result<GeneratedSkeleton> ExportGeneratedSkeleton(const Skeleton& skeleton, bool with_mesh, BufferWriter& buffer,
                                                  tinygltf::Model& model, std::vector<int>& scene_roots);

// The model WriteGltf writes for `scene`, all but its bytes, which go to `buffer`: nodes,
// meshes and skins, animations, scene, asset.
Status BuildExportModel(const Scene& scene, const ExportOptions& options, BufferWriter& buffer, tinygltf::Model& model);

// The JSON of an exported model (gltf_json_writer.cc), laid out as tinygltf 2.7's serialiser
// lays out the same model, so that the bytes of our files do not depend on which of the two
// wrote them. Only the members an export fills are written; a model with others (textures,
// cameras, extensions, sparse accessors, morph targets) is refused.
// A .glb's JSON chunk, compact, whose binary chunk holds `bin_bytes` bytes (buffers[0]); the
// model has no buffers (the bytes stay with the caller: BufferWriter::TakeBinaryChunk).
Result<std::string> GlbJson(const tinygltf::Model& model, size_t bin_bytes);
// A .gltf file's text, the model's buffers embedded as base64 data URIs, indented by two
// spaces when `pretty`, ending in a newline.
Result<std::string> GltfJson(const tinygltf::Model& model, bool pretty);

}  // namespace mocapfill::gltf_internal
