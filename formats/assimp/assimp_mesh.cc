#include "formats/assimp/assimp_mesh.h"

#include <assimp/material.h>
#include <assimp/mesh.h>
#include <assimp/scene.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

#include "formats/assimp/assimp_fixups.h"

namespace mocapfill::assimp_detail {

namespace {

Eigen::Vector4f BaseColor(const aiScene& scene, const aiMesh& mesh) {
  Eigen::Vector4f out = Eigen::Vector4f::Ones();
  if (mesh.mMaterialIndex >= scene.mNumMaterials) return out;
  const aiMaterial& material = *scene.mMaterials[mesh.mMaterialIndex];
  aiColor4D c;
  if (material.Get(AI_MATKEY_BASE_COLOR, c) == AI_SUCCESS) {
    out = {c.r, c.g, c.b, c.a};
  } else if (material.Get(AI_MATKEY_COLOR_DIFFUSE, c) == AI_SUCCESS) {
    // Legacy (Phong) materials keep opacity apart from the diffuse colour.
    float opacity = 1.0f;
    material.Get(AI_MATKEY_OPACITY, opacity);
    out = {c.r, c.g, c.b, opacity};
  }
  if (!out.allFinite()) return Eigen::Vector4f::Ones();
  return out.cwiseMax(0.0f).cwiseMin(1.0f);
}

// Positions and normals through `xf` (normals by its inverse transpose), UV set 0 and
// the triangle list.
Result<MeshPrimitive> ReadGeometry(const aiMesh& mesh, const Eigen::Matrix4d& xf, const std::string& what) {
  MeshPrimitive prim;
  const unsigned nv = mesh.mNumVertices;
  const Eigen::Matrix3d normal_xf = xf.block<3, 3>(0, 0).inverse().transpose();
  prim.positions.reserve(nv);
  for (unsigned i = 0; i < nv; ++i) {
    const aiVector3D& p = mesh.mVertices[i];
    const Eigen::Vector3d q = xf.block<3, 3>(0, 0) * Eigen::Vector3d(p.x, p.y, p.z) + xf.block<3, 1>(0, 3);
    if (!q.allFinite()) return InvalidData(what + ": vertex " + std::to_string(i) + " is not finite");
    prim.positions.push_back(q.cast<float>());
  }
  if (mesh.mNormals != nullptr) {
    prim.normals.reserve(nv);
    for (unsigned i = 0; i < nv; ++i) {
      const aiVector3D& n = mesh.mNormals[i];
      Eigen::Vector3d m = normal_xf * Eigen::Vector3d(n.x, n.y, n.z);
      const double len = m.norm();
      m = len > 0.0 && std::isfinite(len) ? Eigen::Vector3d(m / len) : Eigen::Vector3d::UnitY();
      prim.normals.push_back(m.cast<float>());
    }
  }
  if (mesh.mTextureCoords[0] != nullptr) {
    prim.texcoords.reserve(nv);
    for (unsigned i = 0; i < nv; ++i) prim.texcoords.emplace_back(mesh.mTextureCoords[0][i].x, mesh.mTextureCoords[0][i].y);
  }
  prim.indices.reserve(static_cast<size_t>(mesh.mNumFaces) * 3);
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines left beside triangles
    for (unsigned k = 0; k < 3; ++k) {
      if (face.mIndices[k] >= nv) return InvalidData(what + ": face " + std::to_string(f) + " indexes past the vertices");
      prim.indices.push_back(face.mIndices[k]);
    }
  }
  return prim;
}

// Skin slot of joint j, adding it with `ibm` on first use.
int SlotOf(int j, const Eigen::Matrix4d& ibm, Skin& skin, std::vector<int>& slot_of_joint) {
  if (slot_of_joint[j] < 0) {
    slot_of_joint[j] = static_cast<int>(skin.joints.size());
    skin.joints.push_back(j);
    skin.inverse_bind_matrices.push_back(ibm);
  }
  return slot_of_joint[j];
}

Status AddSkin(const aiMesh& mesh, const NodeGraph& g, int node, const std::string& name, MeshPrimitive& prim,
               Scene& scene) {
  const std::string what = "mesh '" + name + "'";
  const int num_joints = scene.skeleton.num_joints();
  const Eigen::Matrix4d world_inv = g.world[node].inverse();
  Skin skin;
  skin.name = name;
  std::vector<int> slot_of_joint(num_joints, -1);
  std::vector<std::vector<std::pair<int, float>>> influences(mesh.mNumVertices);
  for (unsigned b = 0; b < mesh.mNumBones; ++b) {
    const aiBone& bone = *mesh.mBones[b];
    const std::string bone_name = bone.mName.C_Str();
    const int v = g.Find(bone_name);
    if (v < 0 || g.joint_of_node[v] < 0)
      return InvalidData(what + ": bone '" + bone_name + "' " + (v < 0 ? "names no node" : "is not a joint"));
    // Positions are baked into scene space, so the IBM absorbs the mesh node transform.
    const Eigen::Matrix4d ibm = MatrixFromRowMajor(&bone.mOffsetMatrix.a1) * world_inv;
    if (!ibm.allFinite()) return InvalidData(what + ": bone '" + bone_name + "' has a non-finite offset matrix");
    const int slot = SlotOf(g.joint_of_node[v], ibm, skin, slot_of_joint);
    for (unsigned w = 0; w < bone.mNumWeights; ++w) {
      const aiVertexWeight& vw = bone.mWeights[w];
      if (vw.mVertexId >= mesh.mNumVertices)
        return InvalidData(what + ": bone '" + bone_name + "' weights vertex " + std::to_string(vw.mVertexId) +
                           " of " + std::to_string(mesh.mNumVertices));
      influences[vw.mVertexId].emplace_back(slot, vw.mWeight);
    }
  }
  // Unweighted vertices follow the joint that carries the mesh node, as a rigid mesh
  // would; without one they follow the first bone.
  const int owner = g.owner_joint[node];
  size_t unweighted = 0;
  prim.joints.resize(mesh.mNumVertices);
  prim.weights.resize(mesh.mNumVertices);
  for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
    std::optional<VertexInfluences> top = TopFourInfluences(std::move(influences[i]));
    if (!top) {
      ++unweighted;
      top = VertexInfluences{};
      top->weights[0] = 1.0f;
      if (owner >= 0) top->slots[0] = SlotOf(owner, g.world[g.joint_node[owner]].inverse(), skin, slot_of_joint);
    }
    prim.joints[i] = top->slots;
    prim.weights[i] = top->weights;
  }
  if (unweighted > 0)
    scene.warnings.push_back(what + ": " + std::to_string(unweighted) + " vertices have no bone weight; bound to '" +
                             scene.skeleton.name(skin.joints[owner >= 0 ? slot_of_joint[owner] : 0]) + "'");
  if (skin.joints.size() > std::numeric_limits<std::uint16_t>::max())
    return Unsupported(what + ": more than 65535 skin joints");
  scene.skins.push_back(std::move(skin));
  return OkStatus();
}

Status AddMesh(const aiScene& ai_scene, const aiMesh& mesh, const NodeGraph& g, int node, Scene& scene) {
  const std::string name = mesh.mName.length > 0 ? mesh.mName.C_Str() : g.names[node];
  const std::string what = "mesh '" + name + "'";
  if (!(mesh.mPrimitiveTypes & aiPrimitiveType_TRIANGLE)) {
    scene.warnings.push_back(what + " has no triangles (points or lines only); dropped");
    return OkStatus();
  }
  const bool skinned = mesh.mNumBones > 0 && scene.skeleton.num_joints() > 0;
  const int owner = g.owner_joint[node];
  // Skinned: scene space at rest. Rigid: the frame of the joint that carries the node.
  Eigen::Matrix4d xf = g.world[node];
  if (!skinned && owner >= 0) xf = g.world[g.joint_node[owner]].inverse() * g.world[node];
  if (!xf.allFinite() || std::abs(xf.block<3, 3>(0, 0).determinant()) < 1e-300)
    return InvalidData(what + ": node '" + g.names[node] + "' has a singular transform");
  ASSIGN_OR_RETURN(MeshPrimitive prim, ReadGeometry(mesh, xf, what));
  prim.base_color = BaseColor(ai_scene, mesh);
  Mesh out;
  out.name = name;
  if (skinned) {
    RETURN_IF_ERROR(AddSkin(mesh, g, node, name, prim, scene));
    out.skin = static_cast<int>(scene.skins.size()) - 1;
  } else {
    out.attach_joint = owner;
  }
  out.primitives.push_back(std::move(prim));
  scene.meshes.push_back(std::move(out));
  return OkStatus();
}

}  // namespace

Status ConvertMeshes(const aiScene& ai_scene, const NodeGraph& g, Scene& scene) {
  for (size_t v = 0; v < g.nodes.size(); ++v) {
    const aiNode& node = *g.nodes[v];
    for (unsigned k = 0; k < node.mNumMeshes; ++k) {
      if (node.mMeshes[k] >= ai_scene.mNumMeshes)
        return InvalidData("node '" + g.names[v] + "' references mesh " + std::to_string(node.mMeshes[k]) +
                           " of " + std::to_string(ai_scene.mNumMeshes));
      RETURN_IF_ERROR(AddMesh(ai_scene, *ai_scene.mMeshes[node.mMeshes[k]], g, static_cast<int>(v), scene));
    }
  }
  return OkStatus();
}

}  // namespace mocapfill::assimp_detail
