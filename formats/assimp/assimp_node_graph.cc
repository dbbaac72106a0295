#include "formats/assimp/assimp_node_graph.h"

#include <assimp/scene.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <utility>

namespace mocapfill::assimp_detail {

static_assert(sizeof(aiMatrix4x4) == 16 * sizeof(float), "Assimp built with ai_real = float is expected");

namespace {

// Helper nodes are named "<node>_$AssimpFbx$_<component>".
constexpr char kFbxHelperTag[] = "_$AssimpFbx$_";

// Nodes are walked with an explicit stack: deep chains (long ropes, tails) must not
// overflow the call stack.
void Flatten(const aiScene& scene, NodeGraph& g) {
  std::vector<std::pair<const aiNode*, int>> stack = {{scene.mRootNode, -1}};
  while (!stack.empty()) {
    const auto [node, parent] = stack.back();
    stack.pop_back();
    const int index = static_cast<int>(g.nodes.size());
    g.nodes.push_back(node);
    g.names.emplace_back(node->mName.C_Str());
    g.parent.push_back(parent);
    g.local.push_back(MatrixFromRowMajor(&node->mTransformation.a1));
    g.world.push_back(parent < 0 ? g.local.back() : Eigen::Matrix4d(g.world[parent] * g.local.back()));
    g.by_name.emplace(g.names.back(), index);  // keeps the first, as aiNode::FindNode does
    for (unsigned c = node->mNumChildren; c-- > 0;) stack.emplace_back(node->mChildren[c], index);
  }
}

struct NodeRoles {
  std::vector<char> bone, target, skinned, content;
};

NodeRoles FindRoles(const aiScene& scene, const NodeGraph& g) {
  const size_t n = g.nodes.size();
  NodeRoles roles{std::vector<char>(n, 0), std::vector<char>(n, 0), std::vector<char>(n, 0),
                  std::vector<char>(n, 0)};
  for (unsigned m = 0; m < scene.mNumMeshes; ++m)
    for (unsigned b = 0; b < scene.mMeshes[m]->mNumBones; ++b)
      if (const int v = g.Find(scene.mMeshes[m]->mBones[b]->mName.C_Str()); v >= 0) roles.bone[v] = 1;
  std::unordered_set<std::string> attachments;  // cameras and lights are attached to nodes by name
  for (unsigned i = 0; i < scene.mNumCameras; ++i) attachments.insert(scene.mCameras[i]->mName.C_Str());
  for (unsigned i = 0; i < scene.mNumLights; ++i) attachments.insert(scene.mLights[i]->mName.C_Str());
  // An animated camera or light (or one of its pivot helpers) does not make a skeleton.
  for (unsigned a = 0; a < scene.mNumAnimations; ++a) {
    for (unsigned c = 0; c < scene.mAnimations[a]->mNumChannels; ++c) {
      const std::string target = scene.mAnimations[a]->mChannels[c]->mNodeName.C_Str();
      const int v = g.Find(target);
      if (v >= 0 && !attachments.count(target.substr(0, target.find(kFbxHelperTag)))) roles.target[v] = 1;
    }
  }
  for (size_t v = 0; v < n; ++v) {
    const aiNode* node = g.nodes[v];
    for (unsigned k = 0; k < node->mNumMeshes; ++k)
      if (scene.mMeshes[node->mMeshes[k]]->mNumBones > 0) roles.skinned[v] = 1;
    roles.content[v] = node->mNumMeshes > 0 || attachments.count(g.names[v]) > 0;
  }
  return roles;
}

// Marks the nodes of the trees that hold joints. A tree is the subtree of a child of
// the scene root (or the whole scene when the root itself is a bone or animated).
std::vector<char> ChooseJointTrees(const NodeGraph& g, const NodeRoles& roles) {
  const int n = static_cast<int>(g.nodes.size());
  std::vector<char> top(n, 0);
  bool any = false;
  for (int v = 0; v < n; ++v) {
    if (!roles.bone[v] && !roles.target[v]) continue;
    any = true;
    int t = v;
    while (t != 0 && g.parent[t] != 0) t = g.parent[t];
    top[t] = 1;
  }
  if (!any) {
    // A static skeleton: transform-only hierarchies of at least two nodes.
    std::vector<int> size(n, 1);
    std::vector<char> content = roles.content;
    for (int v = n - 1; v > 0; --v) {
      size[g.parent[v]] += size[v];
      content[g.parent[v]] |= content[v];
    }
    for (int v = 1; v < n; ++v)
      if (g.parent[v] == 0 && !content[v] && size[v] >= 2) top[v] = 1;
  }
  std::vector<char> in_tree(n, 0);
  for (int v = 0; v < n; ++v) in_tree[v] = top[v] || (g.parent[v] >= 0 && in_tree[g.parent[v]]);
  return in_tree;
}

std::string UniqueJointName(const NodeGraph& g, int v, std::unordered_set<std::string>& used,
                            std::vector<std::string>& warnings) {
  std::string name = g.names[v];
  if (name.empty()) {
    name = "node_" + std::to_string(v);
    warnings.push_back("a joint node has no name; called it '" + name + "'");
  }
  if (used.count(name)) {
    int k = 1;
    while (used.count(name + "_" + std::to_string(k))) ++k;
    const std::string renamed = name + "_" + std::to_string(k);
    warnings.push_back("duplicate joint name '" + name + "' renamed to '" + renamed +
                       "' (bones and animation channels bind to the first node of that name)");
    name = renamed;
  }
  used.insert(name);
  return name;
}

}  // namespace

Eigen::Matrix4d MatrixFromRowMajor(const float* m16) {
  Eigen::Matrix4d m;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m(r, c) = m16[r * 4 + c];
  return m;
}

bool IsFbxHelperNode(const std::string& name) { return name.find("$AssimpFbx$") != std::string::npos; }

Trs Decompose(const Eigen::Matrix4d& m) {
  Trs trs;
  trs.translation = m.block<3, 1>(0, 3);
  Eigen::Matrix3d a = m.block<3, 3>(0, 0);
  for (int i = 0; i < 3; ++i) trs.scale[i] = a.col(i).norm();
  if (a.determinant() < 0.0) trs.scale.x() = -trs.scale.x();
  if (trs.scale.cwiseAbs().minCoeff() < 1e-12) return trs;  // degenerate: no rotation to recover
  for (int i = 0; i < 3; ++i) a.col(i) /= trs.scale[i];
  if ((a.transpose() * a - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-9) {
    // Sheared (non-uniform scale under a rotated child): take the nearest rotation.
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
    a = svd.matrixU() * svd.matrixV().transpose();
  }
  trs.rotation = Eigen::Quaterniond(a).normalized();
  return trs;
}

Eigen::Matrix4d Compose(const Trs& trs) {
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<3, 3>(0, 0) = trs.rotation.toRotationMatrix() * trs.scale.asDiagonal();
  m.block<3, 1>(0, 3) = trs.translation;
  return m;
}

Result<ImportedSkeleton> BuildSkeleton(const aiScene& scene, std::vector<std::string>& warnings) {
  if (scene.mRootNode == nullptr) return InvalidData("the scene has no root node");
  ImportedSkeleton out;
  NodeGraph& g = out.graph;
  Flatten(scene, g);
  const int n = static_cast<int>(g.nodes.size());
  const NodeRoles roles = FindRoles(scene, g);
  const std::vector<char> in_tree = ChooseJointTrees(g, roles);

  g.joint_of_node.assign(n, -1);
  g.owner_joint.assign(n, -1);
  g.in_chain.assign(n, 0);
  std::vector<Joint> joints;
  std::unordered_set<std::string> used_names;
  for (int v = 0; v < n; ++v) {
    const int p = g.parent[v];
    const bool is_joint = in_tree[v] && !IsFbxHelperNode(g.names[v]) && (!roles.skinned[v] || roles.bone[v]);
    if (!is_joint) {
      g.owner_joint[v] = p < 0 ? -1 : g.owner_joint[p];
      continue;
    }
    const int j = static_cast<int>(joints.size());
    g.joint_of_node[v] = g.owner_joint[v] = j;
    g.joint_node.push_back(v);
    // The chain runs up to (excluding) the parent joint's node, or through the scene root.
    std::vector<int> chain;
    for (int c = v; c >= 0 && (c == v || g.joint_of_node[c] < 0); c = g.parent[c]) chain.push_back(c);
    std::reverse(chain.begin(), chain.end());
    Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
    for (int c : chain) {
      local = local * g.local[c];
      g.in_chain[c] = 1;
    }
    g.chains.push_back(std::move(chain));

    Joint joint;
    joint.name = UniqueJointName(g, v, used_names, warnings);
    joint.parent = p < 0 ? kNoParent : g.owner_joint[p];
    const Trs rest = Decompose(local);
    joint.rest_translation = rest.translation;
    joint.rest_rotation = rest.rotation;
    joint.rest_scale = rest.scale;
    joints.push_back(std::move(joint));
  }
  if (joints.empty()) return out;
  ASSIGN_OR_RETURN(out.skeleton, Skeleton::Build(std::move(joints)));
  return out;
}

}  // namespace mocapfill::assimp_detail
