// Node graph checks and skeleton selection for the glTF reader.
#include "formats/gltf/tinygltf_private.h"

#include <Eigen/Geometry>
#include <cmath>
#include <set>

#include "formats/gltf/gltf_import_internal.h"

namespace mocapfill::gltf_internal {

namespace {

std::string NodeField(int i) { return "nodes[" + Str(i) + "]"; }

bool AllFinite(const std::vector<double>& v) {
  for (double x : v)
    if (!std::isfinite(x)) return false;
  return true;
}

Status CheckTransform(const tinygltf::Node& node, int i) {
  const std::string field = NodeField(i);
  if (!node.translation.empty() && (node.translation.size() != 3 || !AllFinite(node.translation)))
    return InvalidData(field + ".translation: expected 3 finite numbers");
  if (!node.scale.empty() && (node.scale.size() != 3 || !AllFinite(node.scale)))
    return InvalidData(field + ".scale: expected 3 finite numbers");
  if (!node.rotation.empty()) {
    if (node.rotation.size() != 4 || !AllFinite(node.rotation))
      return InvalidData(field + ".rotation: expected 4 finite numbers (x, y, z, w)");
    const double norm = Eigen::Vector4d(node.rotation.data()).norm();
    if (norm < 1e-6) return InvalidData(field + ".rotation: zero-length quaternion");
  }
  if (!node.matrix.empty()) {
    if (node.matrix.size() != 16 || !AllFinite(node.matrix))
      return InvalidData(field + ".matrix: expected 16 finite numbers");
    const Eigen::Matrix4d m = Eigen::Map<const Eigen::Matrix4d>(node.matrix.data());
    if (m.row(3) != Eigen::RowVector4d(0, 0, 0, 1)) return InvalidData(field + ".matrix: last row is not (0, 0, 0, 1)");
    if (std::abs(m.block<3, 3>(0, 0).determinant()) < 1e-12) return InvalidData(field + ".matrix: singular (zero scale)");
  }
  return OkStatus();
}

Status CheckReferences(const tinygltf::Model& model, const tinygltf::Node& node, int i) {
  const int n = static_cast<int>(model.nodes.size());
  for (int c : node.children) {
    if (c < 0 || c >= n)
      return InvalidData(NodeField(i) + ".children: node " + Str(c) + " out of range (" + Str(n) + " nodes)");
    if (c == i) return InvalidData(NodeField(i) + ": is its own child (cyclic node graph)");
  }
  if (node.mesh >= static_cast<int>(model.meshes.size()) || node.mesh < -1)
    return InvalidData(NodeField(i) + ".mesh: mesh " + Str(node.mesh) + " out of range (" + Str(model.meshes.size()) + " meshes)");
  if (node.skin >= static_cast<int>(model.skins.size()) || node.skin < -1)
    return InvalidData(NodeField(i) + ".skin: skin " + Str(node.skin) + " out of range (" + Str(model.skins.size()) + " skins)");
  return CheckTransform(node, i);
}

// After every node has at most one parent, a cycle shows as a parent chain longer than
// the node count; report the loop as a path of indices.
Status CheckAcyclic(const std::vector<int>& parent) {
  const int n = static_cast<int>(parent.size());
  std::vector<char> state(n, 0);  // 0 unvisited, 1 on the current chain, 2 known acyclic
  for (int start = 0; start < n; ++start) {
    std::vector<int> chain;
    int i = start;
    while (i != -1 && state[i] == 0) {
      state[i] = 1;
      chain.push_back(i);
      i = parent[i];
    }
    if (i != -1 && state[i] == 1) {
      std::string path = Str(i);
      for (int k = parent[i]; k != i; k = parent[k]) path += " -> " + Str(k);
      return InvalidData(NodeField(i) + ": is its own ancestor (cyclic node graph, parent chain " + path + " -> " +
                         Str(i) + ")");
    }
    for (int c : chain) state[c] = 2;
  }
  return OkStatus();
}

bool IsSkinnedMeshNode(const tinygltf::Node& node) { return node.mesh >= 0 && node.skin >= 0; }

// Nodes that must be joints before the tree rule applies: skin joints, animated nodes.
Result<std::vector<char>> SeedJoints(const tinygltf::Model& model) {
  const int n = static_cast<int>(model.nodes.size());
  std::vector<char> seed(n, 0);
  for (size_t s = 0; s < model.skins.size(); ++s) {
    for (int j : model.skins[s].joints) {
      if (j < 0 || j >= n)
        return InvalidData("skins[" + Str(s) + "].joints: node " + Str(j) + " out of range (" + Str(n) + " nodes)");
      seed[j] = 1;
    }
  }
  for (size_t a = 0; a < model.animations.size(); ++a) {
    const auto& channels = model.animations[a].channels;
    for (size_t c = 0; c < channels.size(); ++c) {
      const tinygltf::AnimationChannel& ch = channels[c];
      if (ch.target_path != "translation" && ch.target_path != "rotation" && ch.target_path != "scale") continue;
      if (ch.target_node < -1 || ch.target_node >= n)
        return InvalidData("animations[" + Str(a) + "].channels[" + Str(c) + "].target.node: node " +
                           Str(ch.target_node) + " out of range (" + Str(n) + " nodes)");
      // A skinned-mesh node is not a joint (its transform does not move the skin).
      if (ch.target_node >= 0 && !IsSkinnedMeshNode(model.nodes[ch.target_node])) seed[ch.target_node] = 1;
    }
  }
  return seed;
}

}  // namespace

std::vector<int> SceneOrder(const tinygltf::Model& model, const std::vector<int>& roots) {
  std::vector<int> order;
  std::vector<int> stack(roots.rbegin(), roots.rend());
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    order.push_back(i);
    const auto& children = model.nodes[i].children;
    stack.insert(stack.end(), children.rbegin(), children.rend());
  }
  return order;
}

namespace {

std::vector<std::string> UniqueNames(const tinygltf::Model& model, const std::vector<int>& nodes,
                                     std::vector<std::string>& warnings) {
  std::set<std::string> taken;
  for (int i : nodes) taken.insert(model.nodes[i].name);
  std::set<std::string> used;
  std::vector<std::string> names;
  for (int i : nodes) {
    std::string name = model.nodes[i].name.empty() ? "node_" + Str(i) : model.nodes[i].name;
    if (used.count(name)) {
      std::string candidate;
      for (int k = 2; candidate.empty() || used.count(candidate) || taken.count(candidate); ++k)
        candidate = name + "_" + Str(k);
      warnings.push_back(NodeField(i) + ": duplicate name '" + name + "' renamed to '" + candidate + "'");
      name = candidate;
    }
    used.insert(name);
    names.push_back(name);
  }
  return names;
}

void ReadJointExtras(const tinygltf::Value& extras, Joint& joint) {
  if (!extras.IsObject()) return;
  const tinygltf::Value& channels = extras.Get("bvh_channels");
  for (size_t k = 0; k < channels.ArrayLen(); ++k)
    if (channels.Get(static_cast<int>(k)).IsString()) joint.bvh_channels.push_back(channels.Get(static_cast<int>(k)).Get<std::string>());
  const tinygltf::Value& end = extras.Get("bvh_end_site");
  if (end.ArrayLen() == 3) {
    Eigen::Vector3d v;
    for (int c = 0; c < 3; ++c) v[c] = end.Get(c).IsNumber() ? end.Get(c).GetNumberAsDouble() : NAN;
    if (v.allFinite()) joint.end_site = v;
  }
}

void SetRestTransform(const tinygltf::Node& node, Joint& joint) {
  if (!node.matrix.empty()) {
    const Eigen::Matrix4d m = Eigen::Map<const Eigen::Matrix4d>(node.matrix.data());
    Eigen::Matrix3d linear = m.block<3, 3>(0, 0);
    Eigen::Vector3d scale = linear.colwise().norm();
    if (linear.determinant() < 0) scale.x() = -scale.x();  // a mirror goes into the scale
    joint.rest_translation = m.block<3, 1>(0, 3);
    joint.rest_scale = scale;
    joint.rest_rotation = Eigen::Quaterniond(Eigen::Matrix3d(linear * scale.cwiseInverse().asDiagonal())).normalized();
    return;
  }
  if (!node.translation.empty()) joint.rest_translation = Eigen::Vector3d(node.translation.data());
  if (!node.scale.empty()) joint.rest_scale = Eigen::Vector3d(node.scale.data());
  if (!node.rotation.empty())
    joint.rest_rotation =
        Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]).normalized();
}

}  // namespace

Eigen::Matrix4d NodeLocalMatrix(const tinygltf::Model& model, int i) {
  const tinygltf::Node& node = model.nodes[i];
  if (!node.matrix.empty()) return Eigen::Map<const Eigen::Matrix4d>(node.matrix.data());
  Joint trs;
  SetRestTransform(node, trs);
  Eigen::Affine3d a = Eigen::Translation3d(trs.rest_translation) * trs.rest_rotation * Eigen::Scaling(trs.rest_scale);
  return a.matrix();
}

Result<NodeGraph> CheckNodeGraph(const tinygltf::Model& model) {
  const int n = static_cast<int>(model.nodes.size());
  NodeGraph graph;
  graph.parent.assign(n, -1);
  for (int i = 0; i < n; ++i) {
    RETURN_IF_ERROR(CheckReferences(model, model.nodes[i], i));
    for (int c : model.nodes[i].children) {
      if (graph.parent[c] != -1)
        return InvalidData(NodeField(c) + ": has two parents (nodes " + Str(graph.parent[c]) + " and " + Str(i) +
                           "); a node may have only one");
      graph.parent[c] = i;
    }
  }
  RETURN_IF_ERROR(CheckAcyclic(graph.parent));
  const int scene_count = static_cast<int>(model.scenes.size());
  if (model.defaultScene >= scene_count || (model.defaultScene < 0 && model.defaultScene != -1))
    return InvalidData("scene: index " + Str(model.defaultScene) + " out of range (" + Str(scene_count) + " scenes)");
  if (scene_count > 0) {
    const int s = std::max(model.defaultScene, 0);
    for (int r : model.scenes[s].nodes) {
      if (r < 0 || r >= n) return InvalidData("scenes[" + Str(s) + "].nodes: node " + Str(r) + " out of range (" + Str(n) + " nodes)");
      if (graph.parent[r] != -1)
        return InvalidData("scenes[" + Str(s) + "].nodes: node " + Str(r) + " is not a root (its parent is node " +
                           Str(graph.parent[r]) + ")");
      graph.scene_roots.push_back(r);
    }
  } else {
    for (int i = 0; i < n; ++i)
      if (graph.parent[i] == -1) graph.scene_roots.push_back(i);
  }
  return graph;
}

Result<SkeletonImport> ImportSkeleton(const tinygltf::Model& model, const NodeGraph& graph,
                                      std::vector<std::string>& warnings) {
  ASSIGN_OR_RETURN(std::vector<char> seed, SeedJoints(model));
  const int n = static_cast<int>(seed.size());
  for (int i = 0; i < n; ++i)  // close over ancestors
    if (seed[i])
      for (int p = graph.parent[i]; p != -1 && !seed[p]; p = graph.parent[p]) seed[p] = 1;
  // A skinned-mesh node is not a joint, even above the skeleton (as in the Khronos skin
  // tutorial), as long as dropping it changes no transform: it must be an identity.
  std::vector<char> transparent(n, 0);
  for (int i = 0; i < n; ++i)
    transparent[i] = IsSkinnedMeshNode(model.nodes[i]) && NodeLocalMatrix(model, i).isIdentity(0.0);
  const std::vector<int> order = SceneOrder(model, graph.scene_roots);
  bool any_seed = false;
  for (int i : order) any_seed = any_seed || (seed[i] && !transparent[i]);

  SkeletonImport out;
  out.node_to_joint.assign(n, -1);
  std::vector<int> joint_parent(n, -1);  // nearest joint above each node, looking through transparent nodes
  std::vector<int> joint_nodes;
  for (int i : order) {
    int parent = graph.parent[i];
    while (parent != -1 && transparent[parent]) parent = graph.parent[parent];
    const bool parent_is_joint = parent != -1 && out.node_to_joint[parent] != -1;
    // Without skins or animation every mesh-less node is a joint (a static skeleton).
    const bool joint = (seed[i] && !transparent[i]) ||
                       (model.nodes[i].mesh < 0 && (parent_is_joint || (parent == -1 && !any_seed)));
    if (!joint) continue;
    joint_parent[i] = parent;
    out.node_to_joint[i] = static_cast<int>(joint_nodes.size());
    joint_nodes.push_back(i);
  }
  if (joint_nodes.empty())
    return InvalidData("no skeleton: the scene has no skin joints, animated nodes or mesh-less nodes");
  if (joint_nodes.size() > static_cast<size_t>(kMaxSkeletonJoints))
    return InvalidData("nodes: " + Str(joint_nodes.size()) + " joints, more than the " + Str(kMaxSkeletonJoints) +
                       " of a character rig");

  const std::vector<std::string> names = UniqueNames(model, joint_nodes, warnings);
  std::vector<Joint> joints(joint_nodes.size());
  for (size_t j = 0; j < joint_nodes.size(); ++j) {
    const tinygltf::Node& node = model.nodes[joint_nodes[j]];
    joints[j].name = names[j];
    const int parent = joint_parent[joint_nodes[j]];
    joints[j].parent = parent == -1 ? kNoParent : out.node_to_joint[parent];
    SetRestTransform(node, joints[j]);
    ReadJointExtras(node.extras, joints[j]);
  }
  ASSIGN_OR_RETURN(out.skeleton, Skeleton::Build(std::move(joints)));
  out.joint_to_node = std::move(joint_nodes);
  return out;
}

}  // namespace mocapfill::gltf_internal
