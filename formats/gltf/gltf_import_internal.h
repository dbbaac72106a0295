// Internal to formats/gltf: the reader's stages over a model loaded by tinygltf. tinygltf
// stays out of headers; the model is only forward-declared here (under its private name).
#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include "formats/gltf/gltf_str.h"
#include "formats/gltf/tinygltf_name.h"
#include "processing/core/scene.h"
#include "processing/core/status.h"

namespace tinygltf {
class Model;
}

namespace mocapfill::gltf_internal {

// An accessor's elements as doubles: normalised integers are mapped to [0, 1] / [-1, 1]
// as the spec says, other integers keep their value.
struct AccessorData {
  size_t count = 0;
  int components = 0;      // per element: 1 SCALAR, 2 VEC2, ..., 16 MAT4
  int component_type = 0;  // glTF code, e.g. 5126 FLOAT
  bool normalized = false;
  std::vector<double> values;  // count * components
};

// Reads accessors[index] (dense part and sparse substitution), checking every index,
// offset and length against the model first. Errors are kInvalidData and start with
// "accessors[i]: ", e.g. "accessors[3]: buffer view 7 out of range (5 buffer views)".
Result<AccessorData> ReadAccessor(const tinygltf::Model& model, int index);

// Parent of every node (-1 for none) and the nodes the imported scene starts from.
struct NodeGraph {
  std::vector<int> parent;
  std::vector<int> scene_roots;  // the default scene's nodes, or every parentless node
};

// Checks node references (children, mesh, skin, scenes) and rejects cyclic graphs
// (a node that is its own ancestor) and nodes with two parents.
Result<NodeGraph> CheckNodeGraph(const tinygltf::Model& model);

// Pre-order over the trees under `roots`, children in their listed order: parents first.
// Valid after CheckNodeGraph succeeded (no cycles).
std::vector<int> SceneOrder(const tinygltf::Model& model, const std::vector<int>& roots);

// A node's local transform (TRS or matrix); valid after CheckNodeGraph succeeded.
Eigen::Matrix4d NodeLocalMatrix(const tinygltf::Model& model, int node);

struct SkeletonImport {
  Skeleton skeleton;
  std::vector<int> node_to_joint;  // per node; -1 when the node is not a joint
  std::vector<int> joint_to_node;
};

// Chooses the joints (skin joints, animated nodes, their ancestors, and the other mesh-less
// nodes of those trees), orders them parents first, names them uniquely and reads their
// rest transforms and BVH extras.
Result<SkeletonImport> ImportSkeleton(const tinygltf::Model& model, const NodeGraph& graph,
                                      std::vector<std::string>& warnings);

// Skinned and rigid meshes of the scene (and the skins they use) into `scene`, whose
// skeleton must already be set from `skeleton`; all but the stick figure our writer made
// (GeneratedSkeletonMesh).
Status ImportMeshes(const tinygltf::Model& model, const NodeGraph& graph, const SkeletonImport& skeleton,
                    Scene& scene);

// The index of the stick-figure mesh our writer made (gltf_generated.h), or -1.
int GeneratedSkeletonMesh(const tinygltf::Model& model);

// A clip as our exporter recorded it in asset.extras.mocapfill.
struct RecordedClip {
  std::string name;
  double sample_rate_hz = 0.0;
  bool has_keys = false;                  // sparse keys were recorded (dense clips record none)
  // The clip had explicit (non-uniform) frame times: the recorded key frames index the
  // written samples (channel keys), not frames of sample_rate_hz.
  bool explicit_frame_times = false;
  std::map<std::string, JointKeys> keys;  // by joint name (frames only)
};

struct AnimationRequest {
  std::string selection;  // ImportOptions::animation
  double rate_hz = 0.0;   // ImportOptions::rate_hz
  std::vector<RecordedClip> recorded;
};

// Samples the requested animations onto the frame grid (see ReadGltf for the rules).
Result<std::vector<MotionClip>> ImportAnimations(const tinygltf::Model& model, const SkeletonImport& skeleton,
                                                 const AnimationRequest& request, std::vector<std::string>& warnings);

}  // namespace mocapfill::gltf_internal
