// Meshes and skins of a glTF scene into Scene::meshes / Scene::skins.
#include "formats/gltf/tinygltf_private.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <map>

#include "formats/gltf/gltf_generated.h"
#include "formats/gltf/gltf_import_internal.h"
#include "formats/gltf/gltf_weights.h"

namespace mocapfill::gltf_internal {

namespace {

bool IsIntegerType(int component_type) {
  return component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE ||
         component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ||
         component_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT;
}

// Reads attribute `name` of a primitive when present: `components` per element, `count`
// elements (0 = any). Returns an empty AccessorData when the attribute is absent.
Result<AccessorData> ReadAttribute(const tinygltf::Model& model, const tinygltf::Primitive& prim, const std::string& name,
                                   int components, size_t count, const std::string& field) {
  const auto it = prim.attributes.find(name);
  if (it == prim.attributes.end()) return AccessorData{};
  Result<AccessorData> data = ReadAccessor(model, it->second);
  if (!data.ok()) return data.status().WithContext(field + ".attributes." + name);
  if (data->components != components || (count && data->count != count))
    return InvalidData(field + ".attributes." + name + ": accessor " + Str(it->second) + " has " + Str(data->count) +
                       " elements of " + Str(data->components) + " components; expected " +
                       (count ? Str(count) : std::string("some")) + " of " + Str(components));
  for (double v : data->values)
    if (!std::isfinite(v)) return InvalidData(field + ".attributes." + name + ": non-finite value");
  return data;
}

Status ReadIndices(const tinygltf::Model& model, const tinygltf::Primitive& prim, size_t vertices,
                   const std::string& field, MeshPrimitive& out) {
  if (prim.indices < 0) {
    if (vertices % 3) return InvalidData(field + ": " + Str(vertices) + " vertices do not make whole triangles");
    return OkStatus();
  }
  Result<AccessorData> data = ReadAccessor(model, prim.indices);
  if (!data.ok()) return data.status().WithContext(field + ".indices");
  if (data->components != 1 || !IsIntegerType(data->component_type) || data->normalized)
    return InvalidData(field + ".indices: accessor " + Str(prim.indices) + " is not SCALAR unsigned integers");
  if (data->count % 3) return InvalidData(field + ".indices: " + Str(data->count) + " indices do not make whole triangles");
  out.indices.reserve(data->count);
  for (size_t k = 0; k < data->count; ++k) {
    const double v = data->values[k];
    if (v >= static_cast<double>(vertices))
      return InvalidData(field + ".indices: index " + Str(static_cast<int64_t>(v)) + " at position " + Str(k) +
                         " is out of range (" + Str(vertices) + " vertices)");
    out.indices.push_back(static_cast<uint32_t>(v));
  }
  return OkStatus();
}

// Skin influences from every JOINTS_n / WEIGHTS_n set: a joint listed twice is merged,
// the 4 largest weights are kept and renormalised to sum 1 (FBX-sourced files often do not).
Status ReadSkinning(const tinygltf::Model& model, const tinygltf::Primitive& prim, size_t vertices, size_t skin_joints,
                    const std::string& field, MeshPrimitive& out, std::vector<std::string>& warnings) {
  std::vector<AccessorData> joint_sets, weight_sets;
  for (int set = 0; prim.attributes.count("JOINTS_" + Str(set)); ++set) {
    const std::string joints_name = "JOINTS_" + Str(set), weights_name = "WEIGHTS_" + Str(set);
    if (!prim.attributes.count(weights_name)) return InvalidData(field + ": " + joints_name + " without " + weights_name);
    ASSIGN_OR_RETURN(AccessorData joints, ReadAttribute(model, prim, joints_name, 4, vertices, field));
    ASSIGN_OR_RETURN(AccessorData weights, ReadAttribute(model, prim, weights_name, 4, vertices, field));
    if (!IsIntegerType(joints.component_type) || joints.normalized)
      return InvalidData(field + ".attributes." + joints_name + ": not unsigned integers");
    joint_sets.push_back(std::move(joints));
    weight_sets.push_back(std::move(weights));
  }
  if (joint_sets.empty()) return InvalidData(field + ": a skinned mesh needs JOINTS_0 and WEIGHTS_0 attributes");
  int zero_sums = 0, trimmed = 0;
  out.joints.resize(vertices);
  out.weights.resize(vertices);
  std::vector<std::pair<double, int>> influences;  // (weight, joint)
  for (size_t v = 0; v < vertices; ++v) {
    influences.clear();
    for (size_t set = 0; set < joint_sets.size(); ++set) {
      for (int c = 0; c < 4; ++c) {
        const double index = joint_sets[set].values[v * 4 + c];
        const double weight = weight_sets[set].values[v * 4 + c];
        if (index >= static_cast<double>(skin_joints))
          return InvalidData(field + ".attributes.JOINTS_" + Str(set) + ": joint " + Str(static_cast<int64_t>(index)) +
                             " of vertex " + Str(v) + " is out of range (the skin has " + Str(skin_joints) + " joints)");
        if (!(weight > 0)) continue;
        const int joint = static_cast<int>(index);
        auto same = std::find_if(influences.begin(), influences.end(), [&](const auto& p) { return p.second == joint; });
        if (same != influences.end()) same->first += weight; else influences.emplace_back(weight, joint);
      }
    }
    if (influences.size() > 4) {
      // Largest first; ties by joint index so that the result does not depend on slot order.
      // Up to 4 influences keep their slot order, so a valid file reads back as written.
      std::sort(influences.begin(), influences.end(),
                [](const auto& a, const auto& b) { return a.first != b.first ? a.first > b.first : a.second < b.second; });
      ++trimmed;
    }
    std::array<std::uint16_t, 4> joints{0, 0, 0, 0};
    Eigen::Vector4d w = Eigen::Vector4d::Zero();
    for (size_t k = 0; k < influences.size() && k < 4; ++k) {
      joints[k] = static_cast<std::uint16_t>(influences[k].second);
      w[k] = influences[k].first;
    }
    if (influences.empty()) joints[0] = static_cast<std::uint16_t>(joint_sets[0].values[v * 4]);
    if (!NormaliseInfluences(joints, w)) ++zero_sums;
    out.joints[v] = joints;
    out.weights[v] = w.cast<float>();
  }
  if (trimmed)
    warnings.push_back(field + ": " + Str(trimmed) + " vertices had more than 4 skin influences; the 4 largest were kept");
  if (zero_sums)
    warnings.push_back(field + ": " + Str(zero_sums) + " vertices had no skin weight; bound to their first joint");
  return OkStatus();
}

Result<MeshPrimitive> ReadPrimitive(const tinygltf::Model& model, const tinygltf::Primitive& prim, int skin_joints,
                                    const Eigen::Matrix4d& transform, const std::string& field,
                                    std::vector<std::string>& warnings) {
  MeshPrimitive out;
  if (prim.attributes.count("POSITION") == 0) return InvalidData(field + ": no POSITION attribute");
  ASSIGN_OR_RETURN(AccessorData positions, ReadAttribute(model, prim, "POSITION", 3, 0, field));
  const size_t n = positions.count;
  ASSIGN_OR_RETURN(AccessorData normals, ReadAttribute(model, prim, "NORMAL", 3, n, field));
  ASSIGN_OR_RETURN(AccessorData texcoords, ReadAttribute(model, prim, "TEXCOORD_0", 2, n, field));
  const Eigen::Matrix3d normal_matrix = transform.block<3, 3>(0, 0).inverse().transpose();
  for (size_t v = 0; v < n; ++v) {
    const Eigen::Vector4d p(positions.values[3 * v], positions.values[3 * v + 1], positions.values[3 * v + 2], 1.0);
    out.positions.push_back((transform * p).head<3>().cast<float>());
    if (normals.count) {
      const Eigen::Vector3d nrm = normal_matrix * Eigen::Vector3d(&normals.values[3 * v]);
      out.normals.push_back((nrm.norm() > 0 ? nrm.normalized() : nrm).cast<float>());
    }
    if (texcoords.count) out.texcoords.emplace_back(texcoords.values[2 * v], texcoords.values[2 * v + 1]);
  }
  RETURN_IF_ERROR(ReadIndices(model, prim, n, field, out));
  if (skin_joints > 0) RETURN_IF_ERROR(ReadSkinning(model, prim, n, skin_joints, field, out, warnings));
  if (prim.material >= 0) {
    if (static_cast<size_t>(prim.material) >= model.materials.size())
      return InvalidData(field + ".material: material " + Str(prim.material) + " out of range (" +
                         Str(model.materials.size()) + " materials)");
    const std::vector<double>& c = model.materials[prim.material].pbrMetallicRoughness.baseColorFactor;
    if (c.size() == 4) out.base_color = Eigen::Vector4f(c[0], c[1], c[2], c[3]);
  }
  return out;
}

Result<int> ImportSkin(const tinygltf::Model& model, int s, const SkeletonImport& skeleton, Scene& scene) {
  const tinygltf::Skin& gltf_skin = model.skins[s];
  const std::string field = "skins[" + Str(s) + "]";
  Skin skin;
  skin.name = gltf_skin.name;
  if (gltf_skin.joints.empty()) return InvalidData(field + ".joints: empty");
  for (int node : gltf_skin.joints) {
    if (skeleton.node_to_joint[node] < 0)
      return InvalidData(field + ".joints: node " + Str(node) + " is not in the imported scene");
    skin.joints.push_back(skeleton.node_to_joint[node]);
  }
  skin.inverse_bind_matrices.assign(skin.joints.size(), Eigen::Matrix4d::Identity());
  if (gltf_skin.inverseBindMatrices >= 0) {
    Result<AccessorData> ibm = ReadAccessor(model, gltf_skin.inverseBindMatrices);
    if (!ibm.ok()) return ibm.status().WithContext(field + ".inverseBindMatrices");
    if (ibm->components != 16 || ibm->count < skin.joints.size())
      return InvalidData(field + ".inverseBindMatrices: accessor has " + Str(ibm->count) + " elements of " +
                         Str(ibm->components) + " components; expected " + Str(skin.joints.size()) + " MAT4");
    for (size_t j = 0; j < skin.joints.size(); ++j) {
      skin.inverse_bind_matrices[j] = Eigen::Map<const Eigen::Matrix4d>(&ibm->values[16 * j]);  // column-major
      if (!skin.inverse_bind_matrices[j].allFinite())
        return InvalidData(field + ".inverseBindMatrices: non-finite value in matrix " + Str(j));
    }
  }
  scene.skins.push_back(std::move(skin));
  return static_cast<int>(scene.skins.size()) - 1;
}

}  // namespace

int GeneratedSkeletonMesh(const tinygltf::Model& model) {
  const tinygltf::Value* v = &model.asset.extras;
  for (const char* key : {"mocapfill", "generated_skeleton", "mesh"}) {
    if (!v->IsObject()) return -1;
    v = &v->Get(key);
  }
  const tinygltf::Value& generated = *v;
  if (!generated.IsInt()) return -1;
  const int mesh = generated.Get<int>();
  if (mesh < 0 || mesh >= static_cast<int>(model.meshes.size()) || model.meshes[mesh].name != kGeneratedSkeletonName)
    return -1;
  return mesh;
}

Status ImportMeshes(const tinygltf::Model& model, const NodeGraph& graph, const SkeletonImport& skeleton, Scene& scene) {
  std::map<int, int> skin_index;  // glTF skin -> Scene::skins
  const int generated = GeneratedSkeletonMesh(model);
  for (int node_index : SceneOrder(model, graph.scene_roots)) {
    const tinygltf::Node& node = model.nodes[node_index];
    if (node.mesh < 0 || node.mesh == generated) continue;
    const tinygltf::Mesh& gltf_mesh = model.meshes[node.mesh];
    Mesh mesh;
    mesh.name = gltf_mesh.name.empty() ? "mesh_" + Str(node.mesh) : gltf_mesh.name;
    Eigen::Matrix4d transform = Eigen::Matrix4d::Identity();
    if (node.skin >= 0) {
      // Skinned vertices live in bind space; the mesh node's own transform does not apply.
      if (!skin_index.count(node.skin)) {
        ASSIGN_OR_RETURN(const int s, ImportSkin(model, node.skin, skeleton, scene));
        skin_index[node.skin] = s;
      }
      mesh.skin = skin_index[node.skin];
    } else {
      // A rigid mesh rides on its nearest joint; transforms of non-joint nodes in between are baked in.
      int i = node_index;
      while (i != -1 && skeleton.node_to_joint[i] < 0) {
        transform = NodeLocalMatrix(model, i) * transform;
        i = graph.parent[i];
      }
      mesh.attach_joint = i == -1 ? -1 : skeleton.node_to_joint[i];
    }
    const int skin_joints = mesh.skin >= 0 ? static_cast<int>(scene.skins[mesh.skin].joints.size()) : 0;
    for (size_t p = 0; p < gltf_mesh.primitives.size(); ++p) {
      const tinygltf::Primitive& prim = gltf_mesh.primitives[p];
      const std::string field = "meshes[" + Str(node.mesh) + "].primitives[" + Str(p) + "]";
      const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
      if (mode != TINYGLTF_MODE_TRIANGLES) {
        scene.warnings.push_back(field + ": mode " + Str(mode) + " is not a triangle list; primitive ignored");
        continue;
      }
      ASSIGN_OR_RETURN(MeshPrimitive primitive, ReadPrimitive(model, prim, skin_joints, transform, field, scene.warnings));
      mesh.primitives.push_back(std::move(primitive));
    }
    if (!mesh.primitives.empty()) scene.meshes.push_back(std::move(mesh));
  }
  return OkStatus();
}

}  // namespace mocapfill::gltf_internal
