// Helpers of the glTF tests: where outputs go, file-level read/write through the glTF
// library alone, a scene built in code, scene comparison, and hand-made sketch files.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "formats/motion_io.h"
#include "processing/core/scene.h"

namespace mocapfill::testing {

// <build>/test-output/gltf/<name>: every glTF these tests write lands there, so that CI
// runs the Khronos validator over all of them (tools/validate_gltf.mjs).
std::string GltfOutputPath(const std::string& name);

Result<Scene> ReadGltfFile(const std::string& path, const ImportOptions& options = {});

// Writes `scene` as GltfOutputPath(name) (.glb or .gltf by the name); returns the path.
Result<std::string> WriteGltfOutput(const Scene& scene, const std::string& name);

// A two-root skeleton (a dancer and a prop), a 120 Hz fully keyed clip with root motion,
// a turn of more than 360 degrees and a stretchy arm, a sparse 30 Hz clip, a skinned mesh
// and a rigid mesh, and BVH provenance (cm, channels, end site).
Scene MakeDancerScene();

// Tolerances of a glTF round trip: float32 storage of animation and mesh data.
constexpr double kRotationToleranceDeg = 1e-4;
constexpr double kTranslationToleranceM = 1e-6;

// Skeleton exactly (names, parents, rest transforms, BVH data), clips within the
// tolerances above with identical rates, frame counts and keys; meshes and skins.
void ExpectScenesMatch(const Scene& expected, const Scene& actual);

// A hand-made keyframed file: nodes and animation channels with arbitrary key times and
// interpolation, written with tinygltf (not our writer) as a .gltf with an embedded buffer.
class SketchGltf {
 public:
  // Adds a node (parent -1 for a scene root); returns its index.
  int AddNode(const std::string& name, int parent, const std::vector<double>& translation = {});
  // Adds a channel to animation `animation` (created on first use). `path` is "rotation"
  // (values x, y, z, w per key) or "translation"/"scale" (x, y, z); CUBICSPLINE values hold
  // (in-tangent, value, out-tangent) per key.
  void AddChannel(const std::string& animation, int node, const std::string& path, const std::vector<float>& times_s,
                  const std::vector<float>& values, const std::string& interpolation = "LINEAR");
  // Serialises to `path`; returns false on failure.
  bool Write(const std::string& path) const;

 private:
  struct Node {
    std::string name;
    int parent;
    std::vector<double> translation;
  };
  struct Channel {
    std::string animation;
    int node;
    std::string path;
    std::vector<float> times, values;
    std::string interpolation;
  };
  std::vector<Node> nodes_;
  std::vector<Channel> channels_;
};

}  // namespace mocapfill::testing
