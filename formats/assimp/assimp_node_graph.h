// The Assimp node tree flattened into tables, and the choice of which nodes are joints.
// Internal to formats/assimp: Assimp types are only forward-declared here, the headers
// are included by the .cc files alone.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <unordered_map>
#include <vector>

#include "processing/core/skeleton.h"
#include "processing/core/status.h"

struct aiNode;
struct aiScene;

namespace mocapfill::assimp_detail {

struct Trs {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
};

// M = T * R * S. A negative determinant is carried by a negative x scale; shear is
// dropped (the rotation is the nearest orthonormal matrix).
Trs Decompose(const Eigen::Matrix4d& m);
Eigen::Matrix4d Compose(const Trs& trs);

// An Assimp 4x4 matrix (row-major, 16 ai_real from a1) as an Eigen matrix.
Eigen::Matrix4d MatrixFromRowMajor(const float* m16);

// True for the helper nodes Assimp's FBX importer adds for pivots and offsets
// ("Hips_$AssimpFbx$_PreRotation").
bool IsFbxHelperNode(const std::string& name);

struct NodeGraph {
  // Per node, in pre-order (parents first); node 0 is the scene root.
  std::vector<const aiNode*> nodes;
  std::vector<std::string> names;
  std::vector<int> parent;              // -1 for the scene root
  std::vector<Eigen::Matrix4d> local;   // rest transform relative to the parent node
  std::vector<Eigen::Matrix4d> world;   // rest transform relative to the scene
  std::vector<int> joint_of_node;       // joint index, or -1
  std::vector<int> owner_joint;         // nearest joint at or above the node, or -1
  std::vector<char> in_chain;           // the node's transform is part of some joint's local transform
  std::unordered_map<std::string, int> by_name;  // first node in pre-order with each name (Assimp's lookup)

  // Per joint: its node, and the nodes whose local transforms compose the joint's local
  // transform: those strictly below the parent joint's node (or from the scene root for
  // top-level joints) down to the joint's own node. Helper and skinned-mesh nodes fold in here.
  std::vector<int> joint_node;
  std::vector<std::vector<int>> chains;

  int Find(const std::string& name) const {
    const auto it = by_name.find(name);
    return it == by_name.end() ? -1 : it->second;
  }
};

struct ImportedSkeleton {
  NodeGraph graph;
  Skeleton skeleton;  // empty when the scene has no joints
};

// Flattens the node tree and picks the joints: nodes named by mesh bones or animation
// channels (except animated cameras and lights), their ancestors below the scene root, and every other transform node in
// those trees, except Assimp helper nodes and nodes that carry skinned meshes. With no
// bones and no animation, pure transform hierarchies (no meshes, cameras or lights) of
// two or more nodes are taken as static skeletons. Duplicate or empty joint names get a
// suffix and a warning.
Result<ImportedSkeleton> BuildSkeleton(const aiScene& scene, std::vector<std::string>& warnings);

}  // namespace mocapfill::assimp_detail
