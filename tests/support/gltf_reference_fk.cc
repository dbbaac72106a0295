#include "tests/support/gltf_reference_fk.h"

#include <tiny_gltf.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstring>
#include <functional>

namespace mocapfill::testing {

namespace {

std::vector<float> ReadFloats(const tinygltf::Model& model, int accessor_index, int components) {
  const tinygltf::Accessor& accessor = model.accessors[accessor_index];
  const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
  const tinygltf::Buffer& buffer = model.buffers[view.buffer];
  const size_t stride = view.byteStride ? view.byteStride : components * sizeof(float);
  std::vector<float> values(accessor.count * components);
  for (size_t i = 0; i < accessor.count; ++i)
    std::memcpy(&values[i * components], buffer.data.data() + view.byteOffset + accessor.byteOffset + i * stride,
                components * sizeof(float));
  return values;
}

struct NodeTrs {
  Eigen::Vector3d t = Eigen::Vector3d::Zero();
  Eigen::Quaterniond r = Eigen::Quaterniond::Identity();
  Eigen::Vector3d s = Eigen::Vector3d::Ones();
};

}  // namespace

bool EvaluateGltfReference(const std::string& path, ReferenceGltfAnimation& out, std::string& error) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string warn;
  const bool binary = path.size() > 4 && path.substr(path.size() - 4) == ".glb";
  const bool ok = binary ? loader.LoadBinaryFromFile(&model, &error, &warn, path)
                         : loader.LoadASCIIFromFile(&model, &error, &warn, path);
  if (!ok) return false;
  if (model.animations.empty()) {
    error = "no animation";
    return false;
  }
  const size_t n = model.nodes.size();
  std::vector<NodeTrs> rest(n);
  std::vector<int> parent(n, -1);
  for (size_t i = 0; i < n; ++i) {
    const tinygltf::Node& node = model.nodes[i];
    if (node.translation.size() == 3) rest[i].t = {node.translation[0], node.translation[1], node.translation[2]};
    if (node.rotation.size() == 4) rest[i].r = Eigen::Quaterniond(node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    if (node.scale.size() == 3) rest[i].s = {node.scale[0], node.scale[1], node.scale[2]};
    for (int c : node.children) parent[c] = static_cast<int>(i);
    out.node_names.push_back(node.name);
  }
  const tinygltf::Animation& animation = model.animations[0];
  out.times = ReadFloats(model, animation.samplers[animation.channels[0].sampler].input, 1);
  std::vector<std::vector<NodeTrs>> frames(out.times.size(), rest);
  for (const tinygltf::AnimationChannel& channel : animation.channels) {
    const tinygltf::AnimationSampler& sampler = animation.samplers[channel.sampler];
    const std::vector<float> times = ReadFloats(model, sampler.input, 1);
    const bool rotation = channel.target_path == "rotation";
    const bool translation = channel.target_path == "translation";
    if (!rotation && !translation) continue;
    const std::vector<float> values = ReadFloats(model, sampler.output, rotation ? 4 : 3);
    for (size_t f = 0; f < out.times.size(); ++f) {
      // Every exported channel is sampled on the shared timeline: find the key at this time.
      const auto it = std::lower_bound(times.begin(), times.end(), out.times[f]);
      const size_t k = std::min<size_t>(it - times.begin(), times.size() - 1);
      NodeTrs& trs = frames[f][channel.target_node];
      if (rotation)
        trs.r = Eigen::Quaterniond(values[4 * k + 3], values[4 * k], values[4 * k + 1], values[4 * k + 2]).normalized();
      else
        trs.t = {values[3 * k], values[3 * k + 1], values[3 * k + 2]};
    }
  }
  out.world_positions.assign(out.times.size(), std::vector<Eigen::Vector3d>(n));
  for (size_t f = 0; f < out.times.size(); ++f) {
    std::vector<Eigen::Matrix4d> world(n);
    std::vector<bool> done(n, false);
    // Nodes may be stored in any order: resolve parents recursively (graphs are small).
    std::function<const Eigen::Matrix4d&(int)> resolve = [&](int i) -> const Eigen::Matrix4d& {
      if (!done[i]) {
        Eigen::Affine3d local = Eigen::Translation3d(frames[f][i].t) * frames[f][i].r * Eigen::Scaling(frames[f][i].s);
        world[i] = parent[i] < 0 ? local.matrix() : Eigen::Matrix4d(resolve(parent[i]) * local.matrix());
        done[i] = true;
      }
      return world[i];
    };
    for (size_t i = 0; i < n; ++i) out.world_positions[f][i] = resolve(static_cast<int>(i)).block<3, 1>(0, 3);
  }
  return true;
}

}  // namespace mocapfill::testing
