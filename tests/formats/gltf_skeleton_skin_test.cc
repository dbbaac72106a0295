// The skin (and stick-figure mesh) the glTF writer adds for a scene without a skinned mesh
// (ExportOptions::gltf_skeleton): read with Debian's libtinygltf, the skin lists every joint
// node with inverse bind matrices that undo the rest pose; the mesh node is skinned, at the
// scene root, untransformed; and mocapfill's reader gives back the same joints and motion,
// without the stick figure.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <cstring>
#include <numeric>
#include <sstream>

#include "formats/gltf/gltf_reader.h"
#include "formats/gltf/gltf_writer.h"
#include "formats/motion_io.h"
#include "tests/formats/gltf_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::FixturePath;

tinygltf::Model Parse(const std::string& glb) {
  tinygltf::TinyGLTF loader;
  tinygltf::Model model;
  std::string error, warning;
  EXPECT_TRUE(loader.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(glb.data()),
                                          static_cast<unsigned>(glb.size())))
      << error;
  return model;
}

template <class T>
std::vector<T> Elements(const tinygltf::Model& model, int accessor, size_t per_element) {
  const tinygltf::Accessor& a = model.accessors[accessor];
  const tinygltf::BufferView& v = model.bufferViews[a.bufferView];
  std::vector<T> out(a.count * per_element);
  std::memcpy(out.data(), model.buffers[v.buffer].data.data() + v.byteOffset + a.byteOffset, out.size() * sizeof(T));
  return out;
}

Eigen::Affine3d NodeRest(const tinygltf::Node& n) {
  Eigen::Affine3d m = Eigen::Affine3d::Identity();
  if (!n.translation.empty()) m.translate(Eigen::Vector3d(n.translation.data()));
  if (!n.rotation.empty()) m.rotate(Eigen::Quaterniond(n.rotation[3], n.rotation[0], n.rotation[1], n.rotation[2]));
  if (!n.scale.empty()) m.scale(Eigen::Vector3d(n.scale.data()));
  return m;
}

Result<std::string> Glb(const Scene& scene, GltfSkeleton skeleton) {
  ExportOptions options;
  options.gltf_skeleton = skeleton;
  return WriteGltf(scene, true, options);
}

std::vector<std::string> Sources() {
  return {FixturePath("bvh/bandai_walk_normal_001_short.bvh"), FixturePath("bvh/cmu_01_01_short.bvh"),
          FixturePath("bvh/cmu_two_roots.bvh"), FixturePath("bvh/boxing_interleaved.bvh")};
}

TEST(GltfSkeletonSkin, EveryJointIsBoundInTheRestPose) {
  for (const std::string& path : Sources()) {
    const Result<Scene> scene = ImportFile(path);
    ASSERT_TRUE(scene.ok()) << path;
    const Result<std::string> glb = Glb(*scene, GltfSkeleton::kSkin);
    ASSERT_TRUE(glb.ok()) << glb.status().message();
    const tinygltf::Model model = Parse(*glb);
    const int joints = scene->skeleton.num_joints();
    ASSERT_EQ(model.skins.size(), 1u) << path;
    EXPECT_TRUE(model.meshes.empty());
    ASSERT_EQ(model.nodes.size(), static_cast<size_t>(joints));
    const tinygltf::Skin& skin = model.skins[0];
    std::vector<int> every(joints);
    for (int j = 0; j < joints; ++j) every[j] = j;
    EXPECT_EQ(skin.joints, every);
    const std::vector<int> roots = scene->skeleton.Roots();
    EXPECT_EQ(skin.skeleton, roots.size() == 1 ? roots[0] : -1) << path;  // no common root across two trees
    ASSERT_GE(skin.inverseBindMatrices, 0);
    EXPECT_EQ(model.accessors[skin.inverseBindMatrices].type, TINYGLTF_TYPE_MAT4);
    const std::vector<float> ibm = Elements<float>(model, skin.inverseBindMatrices, 16);
    ASSERT_EQ(ibm.size(), 16u * joints);
    // World rest transforms from the nodes alone; IBM j times world j is the identity.
    std::vector<Eigen::Affine3d> world(model.nodes.size(), Eigen::Affine3d::Identity());
    std::vector<int> parent(model.nodes.size(), -1);
    for (size_t n = 0; n < model.nodes.size(); ++n)
      for (int c : model.nodes[n].children) parent[c] = static_cast<int>(n);
    double worst = 0.0;
    for (int j = 0; j < joints; ++j) {  // parents first, as the writer numbers them
      world[j] = (parent[j] < 0 ? Eigen::Affine3d::Identity() : world[parent[j]]) * NodeRest(model.nodes[j]);
      const Eigen::Matrix4d m = Eigen::Map<const Eigen::Matrix4f>(&ibm[16 * j]).cast<double>();
      EXPECT_EQ(m.row(3), Eigen::RowVector4d(0, 0, 0, 1));
      worst = std::max(worst, (m * world[j].matrix() - Eigen::Matrix4d::Identity()).cwiseAbs().maxCoeff());
    }
    EXPECT_LT(worst, 1e-6) << path;

    // Read back: the joints and motion of the bare-node file, and no skin of its own.
    const Result<std::string> bare = Glb(*scene, GltfSkeleton::kNodes);
    ASSERT_TRUE(bare.ok());
    EXPECT_TRUE(Parse(*bare).skins.empty());
    const Result<Scene> back = ReadGltf(*glb, "skinned.glb", {});
    const Result<Scene> back_bare = ReadGltf(*bare, "bare.glb", {});
    ASSERT_TRUE(back.ok() && back_bare.ok());
    EXPECT_TRUE(back->meshes.empty());
    EXPECT_TRUE(back->skins.empty());  // a skin no mesh uses is not scene content
    ASSERT_EQ(back->skeleton.num_joints(), back_bare->skeleton.num_joints());
    for (int j = 0; j < joints; ++j) {
      EXPECT_EQ(back->skeleton.name(j), back_bare->skeleton.name(j));
      EXPECT_EQ(back->skeleton.parent(j), back_bare->skeleton.parent(j));
      EXPECT_EQ(back->skeleton.joint(j).rest_translation, back_bare->skeleton.joint(j).rest_translation);
      EXPECT_EQ(back->skeleton.joint(j).rest_rotation.coeffs(), back_bare->skeleton.joint(j).rest_rotation.coeffs());
    }
    ASSERT_EQ(back->clips.size(), 1u);
    ASSERT_EQ(back->clips[0].rotations.size(), back_bare->clips[0].rotations.size());
    bool same = back->clips[0].translations == back_bare->clips[0].translations;
    for (size_t i = 0; i < back->clips[0].rotations.size(); ++i)
      same = same && back->clips[0].rotations[i].coeffs() == back_bare->clips[0].rotations[i].coeffs();
    EXPECT_TRUE(same) << path;
  }
}

TEST(GltfSkeletonSkin, StickFigureIsSkinnedAtTheRootAndLeftOutOnReading) {
  const Result<Scene> scene = ImportFile(FixturePath("bvh/bandai_walk_normal_001_short.bvh"));
  ASSERT_TRUE(scene.ok());
  const Result<std::string> glb = Glb(*scene, GltfSkeleton::kSkinAndMesh);
  ASSERT_TRUE(glb.ok()) << glb.status().message();
  const tinygltf::Model model = Parse(*glb);
  const int joints = scene->skeleton.num_joints();
  ASSERT_EQ(model.skins.size(), 1u);
  ASSERT_EQ(model.meshes.size(), 1u);
  ASSERT_EQ(model.nodes.size(), static_cast<size_t>(joints) + 1);
  const tinygltf::Node& node = model.nodes[joints];
  EXPECT_EQ(node.mesh, 0);
  EXPECT_EQ(node.skin, 0);
  EXPECT_TRUE(node.translation.empty() && node.rotation.empty() && node.scale.empty() && node.matrix.empty());
  const std::vector<int>& roots = model.scenes[0].nodes;
  EXPECT_NE(std::find(roots.begin(), roots.end(), joints), roots.end());
  const tinygltf::Primitive& p = model.meshes[0].primitives.at(0);
  const size_t vertices = model.accessors[p.attributes.at("POSITION")].count;
  // Six vertices per bone with length (parent to child, joint to End Site; the Bandai-Namco
  // End Sites have none), bound to the bone's parent joint.
  std::vector<int> expected_bound(joints, 0);
  for (int j = 0; j < joints; ++j) {
    const Joint& joint = scene->skeleton.joint(j);
    if (joint.parent != kNoParent && joint.rest_translation.norm() >= 1e-4) expected_bound[joint.parent] += 6;
    if (joint.end_site && joint.end_site->norm() >= 1e-4) expected_bound[j] += 6;
  }
  const int expected_vertices = std::accumulate(expected_bound.begin(), expected_bound.end(), 0);
  EXPECT_GE(expected_vertices, 6 * 20);
  EXPECT_EQ(vertices, static_cast<size_t>(expected_vertices));
  const std::vector<std::uint8_t> slots = Elements<std::uint8_t>(model, p.attributes.at("JOINTS_0"), 4);
  const std::vector<float> weights = Elements<float>(model, p.attributes.at("WEIGHTS_0"), 4);
  std::vector<int> bound(joints, 0);
  for (size_t v = 0; v < vertices; ++v) {
    EXPECT_EQ(weights[4 * v], 1.0f);
    EXPECT_EQ(weights[4 * v + 1] + weights[4 * v + 2] + weights[4 * v + 3], 0.0f);
    EXPECT_EQ(slots[4 * v + 1] + slots[4 * v + 2] + slots[4 * v + 3], 0);
    ASSERT_LT(slots[4 * v], joints);
    ++bound[slots[4 * v]];
  }
  EXPECT_EQ(bound, expected_bound);
  // The reader leaves the stick figure out: same joints and motion, no meshes, no skins; a
  // second conversion writes what the first did.
  const Result<Scene> back = ReadGltf(*glb, "mesh.glb", {});
  ASSERT_TRUE(back.ok());
  EXPECT_TRUE(back->meshes.empty());
  EXPECT_TRUE(back->skins.empty());
  EXPECT_EQ(back->skeleton.num_joints(), joints);
  const Result<std::string> second = Glb(*back, GltfSkeleton::kSkinAndMesh);
  ASSERT_TRUE(second.ok());
  EXPECT_EQ(Parse(*second).meshes.size(), 1u);
  EXPECT_EQ(Parse(*second).nodes.size(), static_cast<size_t>(joints) + 1);
  const Result<std::string> without = Glb(*back, GltfSkeleton::kNodes);
  ASSERT_TRUE(without.ok());
  EXPECT_TRUE(Parse(*without).meshes.empty() && Parse(*without).skins.empty());
  // A mesh of that name that our writer did not record is the user's, and is kept.
  tinygltf::Model renamed = model;
  renamed.asset.extras = tinygltf::Value();
  tinygltf::TinyGLTF writer;
  std::ostringstream out;
  ASSERT_TRUE(writer.WriteGltfSceneToStream(&renamed, out, false, true));
  const Result<Scene> kept = ReadGltf(out.str(), "user.glb", {});
  ASSERT_TRUE(kept.ok()) << kept.status().message();
  EXPECT_EQ(kept->meshes.size(), 1u);
}

TEST(GltfSkeletonSkin, ScenesWithTheirOwnSkinGetNoOther) {
  const Result<Scene> skinned = ImportFile(FixturePath("gltf/simple_skin.gltf"));
  ASSERT_TRUE(skinned.ok());
  ASSERT_EQ(skinned->skins.size(), 1u);
  const Result<std::string> glb = Glb(*skinned, GltfSkeleton::kSkinAndMesh);
  ASSERT_TRUE(glb.ok());
  const tinygltf::Model model = Parse(*glb);
  EXPECT_EQ(model.skins.size(), 1u);
  EXPECT_EQ(model.meshes.size(), skinned->meshes.size());
  const Result<Scene> back = ReadGltf(*glb, "skinned.glb", {});
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->meshes.size(), skinned->meshes.size());
}

}  // namespace
}  // namespace mocapfill
