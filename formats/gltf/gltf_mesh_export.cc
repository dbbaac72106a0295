// Meshes, materials and skins of the glTF writer.
#include "formats/gltf/tinygltf_private.h"

#include <algorithm>
#include <map>

#include "formats/gltf/gltf_export_internal.h"
#include "formats/gltf/gltf_weights.h"

namespace mocapfill::gltf_internal {

namespace {

template <typename T>
int AddAttribute(BufferWriter& buffer, const std::vector<T>& data, int component_type, int type, size_t count,
                 int target, const std::vector<double>& min = {}, const std::vector<double>& max = {}) {
  const int view = buffer.AddView(data.data(), data.size() * sizeof(typename std::vector<T>::value_type), target);
  return buffer.AddAccessor(view, 0, component_type, type, count, min, max);
}

Status CheckPrimitive(const MeshPrimitive& p, int skin_joints, const std::string& field) {
  const size_t n = p.positions.size();
  if (n == 0) return Internal(field + ": no positions");
  if ((!p.normals.empty() && p.normals.size() != n) || (!p.texcoords.empty() && p.texcoords.size() != n))
    return Internal(field + ": normals or texcoords do not match the " + Str(n) + " positions");
  if (p.indices.empty() ? n % 3 != 0 : p.indices.size() % 3 != 0)
    return Internal(field + ": not a whole number of triangles");
  for (uint32_t i : p.indices)
    if (i >= n) return Internal(field + ": index " + Str(i) + " out of range");
  for (const Eigen::Vector3f& v : p.positions)
    if (!v.allFinite()) return Internal(field + ": non-finite position");
  if (skin_joints > 0) {
    if (p.joints.size() != n || p.weights.size() != n) return Internal(field + ": skinned without joints/weights per vertex");
    for (const auto& slots : p.joints)
      for (uint16_t s : slots)
        if (s >= skin_joints) return Internal(field + ": joint slot " + Str(s) + " out of the skin's range");
  }
  return OkStatus();
}

int MaterialIndex(const Eigen::Vector4f& color, tinygltf::Model& model, std::map<std::array<float, 4>, int>& known) {
  const std::array<float, 4> key{color[0], color[1], color[2], color[3]};
  const auto it = known.find(key);
  if (it != known.end()) return it->second;
  tinygltf::Material material;
  material.name = "material_" + Str(model.materials.size());
  material.pbrMetallicRoughness.baseColorFactor = {color[0], color[1], color[2], color[3]};
  model.materials.push_back(std::move(material));
  known[key] = static_cast<int>(model.materials.size()) - 1;
  return known[key];
}

tinygltf::Primitive ExportPrimitive(const MeshPrimitive& p, int skin_joints, BufferWriter& buffer,
                                    tinygltf::Model& model, std::map<std::array<float, 4>, int>& materials) {
  tinygltf::Primitive out;
  out.mode = TINYGLTF_MODE_TRIANGLES;
  const size_t n = p.positions.size();
  Eigen::Vector3f lo = p.positions[0], hi = p.positions[0];
  for (const Eigen::Vector3f& v : p.positions) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  out.attributes["POSITION"] = AddAttribute(buffer, p.positions, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n,
                                            TINYGLTF_TARGET_ARRAY_BUFFER, {lo.x(), lo.y(), lo.z()}, {hi.x(), hi.y(), hi.z()});
  // Normals must be unit length; a primitive with a degenerate one goes without normals.
  std::vector<Eigen::Vector3f> normals;
  for (const Eigen::Vector3f& v : p.normals) {
    if (!(v.norm() > 1e-12f) || !v.allFinite()) {
      normals.clear();
      break;
    }
    normals.push_back((v.cast<double>().normalized()).cast<float>());
  }
  if (!normals.empty())
    out.attributes["NORMAL"] = AddAttribute(buffer, normals, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n,
                                            TINYGLTF_TARGET_ARRAY_BUFFER);
  if (!p.texcoords.empty())
    out.attributes["TEXCOORD_0"] = AddAttribute(buffer, p.texcoords, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC2, n,
                                                TINYGLTF_TARGET_ARRAY_BUFFER);
  if (skin_joints > 0) {
    std::vector<std::array<std::uint16_t, 4>> joints = p.joints;
    std::vector<Eigen::Vector4f> weights = p.weights;
    for (size_t v = 0; v < n; ++v) {
      Eigen::Vector4d w = weights[v].cast<double>();
      NormaliseInfluences(joints[v], w);
      weights[v] = w.cast<float>();
    }
    if (skin_joints <= 256) {
      std::vector<std::uint8_t> small;
      for (const auto& j : joints) small.insert(small.end(), j.begin(), j.end());
      out.attributes["JOINTS_0"] = AddAttribute(buffer, small, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_TYPE_VEC4,
                                                n, TINYGLTF_TARGET_ARRAY_BUFFER);
    } else {
      out.attributes["JOINTS_0"] = AddAttribute(buffer, joints, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_VEC4,
                                                n, TINYGLTF_TARGET_ARRAY_BUFFER);
    }
    out.attributes["WEIGHTS_0"] = AddAttribute(buffer, weights, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, n,
                                               TINYGLTF_TARGET_ARRAY_BUFFER);
  }
  if (!p.indices.empty()) {
    // 65535 is the primitive-restart value of 16-bit indices, so it needs 32 bits.
    const uint32_t max_index = *std::max_element(p.indices.begin(), p.indices.end());
    if (max_index < 65535) {
      const std::vector<std::uint16_t> small(p.indices.begin(), p.indices.end());
      out.indices = AddAttribute(buffer, small, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, TINYGLTF_TYPE_SCALAR,
                                 small.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    } else {
      out.indices = AddAttribute(buffer, p.indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR,
                                 p.indices.size(), TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    }
  }
  out.material = MaterialIndex(p.base_color, model, materials);
  return out;
}

}  // namespace

// The closest common ancestor (or self) of the skin's joints, or -1 across separate trees.
namespace {

int CommonRoot(const Skeleton& skeleton, const std::vector<int>& joints) {
  std::vector<int> chain;  // the first joint and its ancestors, nearest first
  for (int j = joints[0]; j != kNoParent; j = skeleton.parent(j)) chain.push_back(j);
  size_t deepest = 0;  // index into chain of the current common ancestor
  for (int joint : joints) {
    int j = joint;
    while (j != kNoParent && std::find(chain.begin() + deepest, chain.end(), j) == chain.end()) j = skeleton.parent(j);
    if (j == kNoParent) return -1;
    deepest = std::find(chain.begin(), chain.end(), j) - chain.begin();
  }
  return chain[deepest];
}

}  // namespace

Result<int> ExportSkin(const Skin& skin, const Skeleton& skeleton, BufferWriter& buffer, tinygltf::Model& model) {
  if (skin.joints.empty() || skin.inverse_bind_matrices.size() != skin.joints.size())
    return Internal("skin '" + skin.name + "': joints and inverse bind matrices do not match");
  tinygltf::Skin out;
  out.name = skin.name;
  std::vector<float> matrices;
  for (size_t k = 0; k < skin.joints.size(); ++k) {
    if (skin.joints[k] < 0 || skin.joints[k] >= skeleton.num_joints())
      return Internal("skin '" + skin.name + "': joint " + Str(skin.joints[k]) + " out of range");
    out.joints.push_back(skin.joints[k]);  // joint j is node j
    Eigen::Matrix4d m = skin.inverse_bind_matrices[k];
    m.row(3) = Eigen::RowVector4d(0, 0, 0, 1);  // exactly affine, as the validator checks
    for (int i = 0; i < 16; ++i) matrices.push_back(static_cast<float>(m(i % 4, i / 4)));  // column-major
  }
  const int view = buffer.AddView(matrices.data(), matrices.size() * sizeof(float));
  out.inverseBindMatrices =
      buffer.AddAccessor(view, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_MAT4, skin.joints.size());
  out.skeleton = CommonRoot(skeleton, skin.joints);
  model.skins.push_back(std::move(out));
  return static_cast<int>(model.skins.size()) - 1;
}

Result<int> ExportMesh(const Mesh& mesh, const std::vector<Skin>& skins, const Skeleton& skeleton, BufferWriter& buffer,
                       tinygltf::Model& model) {
  const std::string field = "mesh '" + mesh.name + "'";
  if (mesh.skin >= static_cast<int>(skins.size()) || mesh.attach_joint >= skeleton.num_joints())
    return Internal(field + ": skin or joint index out of range");
  const int skin_joints = mesh.skin >= 0 ? static_cast<int>(skins[mesh.skin].joints.size()) : 0;
  tinygltf::Mesh out;
  out.name = mesh.name;
  std::map<std::array<float, 4>, int> materials;
  for (size_t m = 0; m < model.materials.size(); ++m) {
    const std::vector<double>& c = model.materials[m].pbrMetallicRoughness.baseColorFactor;
    materials.emplace(std::array<float, 4>{static_cast<float>(c[0]), static_cast<float>(c[1]), static_cast<float>(c[2]),
                                           static_cast<float>(c[3])},
                      static_cast<int>(m));
  }
  for (size_t p = 0; p < mesh.primitives.size(); ++p) {
    RETURN_IF_ERROR(CheckPrimitive(mesh.primitives[p], skin_joints, field + " primitive " + Str(p)));
    out.primitives.push_back(ExportPrimitive(mesh.primitives[p], skin_joints, buffer, model, materials));
  }
  model.meshes.push_back(std::move(out));
  tinygltf::Node node;
  node.name = mesh.name;
  node.mesh = static_cast<int>(model.meshes.size()) - 1;
  model.nodes.push_back(std::move(node));
  return static_cast<int>(model.nodes.size()) - 1;
}

Status ExportMeshes(const Scene& scene, BufferWriter& buffer, tinygltf::Model& model, std::vector<int>& scene_roots) {
  std::map<int, int> skin_index;  // Scene::skins -> glTF skins, only those a mesh uses
  for (const Mesh& mesh : scene.meshes) {
    if (mesh.primitives.empty()) continue;
    if (mesh.skin >= static_cast<int>(scene.skins.size()))
      return Internal("mesh '" + mesh.name + "': skin or joint index out of range");
    ASSIGN_OR_RETURN(const int node_index, ExportMesh(mesh, scene.skins, scene.skeleton, buffer, model));
    if (mesh.skin >= 0) {
      if (!skin_index.count(mesh.skin)) {
        ASSIGN_OR_RETURN(const int s, ExportSkin(scene.skins[mesh.skin], scene.skeleton, buffer, model));
        skin_index[mesh.skin] = s;
      }
      model.nodes[node_index].skin = skin_index[mesh.skin];
    }
    if (mesh.skin < 0 && mesh.attach_joint >= 0) {
      model.nodes[mesh.attach_joint].children.push_back(node_index);
    } else {
      scene_roots.push_back(node_index);
    }
  }
  return OkStatus();
}

}  // namespace mocapfill::gltf_internal
