// Assimp meshes to Scene meshes and skins. Internal to formats/assimp.
#pragma once

#include <string>
#include <vector>

#include "formats/assimp/assimp_node_graph.h"
#include "processing/core/scene.h"
#include "processing/core/status.h"

struct aiScene;

namespace mocapfill::assimp_detail {

// Appends one Mesh per mesh reference of every node (triangles only; point and line
// meshes are dropped with a warning). Skinned meshes are baked into scene space at the
// rest pose (positions, normals) and get a Skin whose inverse bind matrices are
// aiBone::mOffsetMatrix times the inverse of the mesh node's transform; weights are cut
// to the four largest and renormalised. Rigid meshes ride on the nearest joint at or
// above their node (positions in that joint's frame), or on the scene root. Lengths stay
// in source units; `scene.skeleton` must already be built.
Status ConvertMeshes(const aiScene& ai_scene, const NodeGraph& graph, Scene& scene);

}  // namespace mocapfill::assimp_detail
