// An independent forward-kinematics evaluator for glTF files, used by tests to check our
// exporter: it reads the file with tinygltf directly (not through formats/gltf) and
// evaluates node TRS plus LINEAR animation samplers with plain matrix math.
#pragma once

#include <Eigen/Core>
#include <map>
#include <string>
#include <vector>

namespace mocapfill::testing {

struct ReferenceGltfAnimation {
  std::vector<std::string> node_names;
  std::vector<float> times;                           // shared input of the first animation
  // World positions per frame (index into times) and node, metres.
  std::vector<std::vector<Eigen::Vector3d>> world_positions;
};

// Loads `path` (.gltf or .glb) and evaluates the first animation at each of its key times.
// Returns false with `error` set when the file cannot be read.
bool EvaluateGltfReference(const std::string& path, ReferenceGltfAnimation& out, std::string& error);

}  // namespace mocapfill::testing
