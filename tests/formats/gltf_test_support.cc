#include "tests/formats/gltf_test_support.h"

#include <tiny_gltf.h>

#include <cmath>
#include <fstream>
#include <map>

#include "formats/file_io.h"
#include "formats/gltf/gltf_reader.h"
#include "formats/gltf/gltf_writer.h"
#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "tests/support/test_paths.h"

namespace mocapfill::testing {

namespace {

Eigen::Quaterniond Axis(double angle_rad, const Eigen::Vector3d& axis) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle_rad, axis.normalized()));
}

Joint MakeJoint(const std::string& name, int parent, const Eigen::Vector3d& offset,
                const Eigen::Quaterniond& rest = Eigen::Quaterniond::Identity()) {
  Joint joint;
  joint.name = name;
  joint.parent = parent;
  joint.rest_translation = offset;
  joint.rest_rotation = rest;
  joint.bvh_channels = {"Zrotation", "Yrotation", "Xrotation"};
  return joint;
}

Skeleton DancerSkeleton() {
  std::vector<Joint> joints;
  joints.push_back(MakeJoint("Hips", kNoParent, {0, 0.95, 0}));
  joints[0].bvh_channels = {"Xposition", "Yposition", "Zposition", "Zrotation", "Yrotation", "Xrotation"};
  joints.push_back(MakeJoint("Spine", 0, {0, 0.1, 0.01}, Axis(0.1, Eigen::Vector3d::UnitX())));
  joints.push_back(MakeJoint("Head", 1, {0, 0.45, 0}));
  joints[2].end_site = Eigen::Vector3d(0, 0.12, 0);
  joints.push_back(MakeJoint("Left Arm", 1, {0.2, 0.35, 0}, Axis(kPi / 2, Eigen::Vector3d::UnitZ())));
  joints.push_back(MakeJoint("mixamorig:RightArm", 1, {-0.2, 0.35, 0}));
  joints.push_back(MakeJoint("Prop", kNoParent, {1, 0, 0}));
  joints[5].rest_scale = Eigen::Vector3d(2, 2, 2);
  joints[5].bvh_channels.clear();
  return *Skeleton::Build(std::move(joints));
}

MotionClip DanceClip(const Skeleton& s) {
  const int frames = 97;
  MotionClip clip = MotionClip::RestPose(s, frames, 120.0);
  clip.name = "dance";
  for (int f = 0; f < frames; ++f) {
    const double t = f / 120.0, u = f / 96.0;
    // More than a full turn: quaternion signs flip along the way unless kept continuous.
    clip.rotation(f, 0) = Axis(2.5 * 2 * kPi * u, Eigen::Vector3d::UnitY()) * Axis(0.1 * std::sin(9 * t), Eigen::Vector3d::UnitX());
    clip.translation(f, 0) = Eigen::Vector3d(0.5 * std::sin(3 * t), 0.95 + 0.03 * std::sin(14 * t), 1.2 * t);
    clip.rotation(f, 1) = s.joint(1).rest_rotation * Axis(0.3 * std::sin(2 * kPi * t), Eigen::Vector3d::UnitZ());
    clip.rotation(f, 2) = Axis(0.5 * std::sin(3 * t), Eigen::Vector3d::UnitY()) * Axis(0.2 * std::cos(5 * t), Eigen::Vector3d::UnitX());
    clip.rotation(f, 3) = s.joint(3).rest_rotation * Axis(1.2 * std::sin(4 * t), Eigen::Vector3d(1, 0.2, 0));
    clip.translation(f, 3) = s.joint(3).rest_translation + Eigen::Vector3d(0.02 * std::sin(6 * t), 0, 0);
    clip.rotation(f, 4) = Axis(-0.8 + 0.6 * std::cos(4 * t), Eigen::Vector3d::UnitZ());
    clip.rotation(f, 5) = Axis(3 * kPi * u, Eigen::Vector3d(0, 1, 0.3));
  }
  clip.MakeContinuous();
  clip.DetectAnimatedTranslations();
  clip.KeyAllFrames();
  return clip;
}

// A sketch: only the left arm is keyed (4 keys, slerp in between) and the head once.
MotionClip WaveClip(const Skeleton& s) {
  MotionClip clip = MotionClip::RestPose(s, 31, 30.0);
  clip.name = "wave";
  const Eigen::Quaterniond keys[] = {s.joint(3).rest_rotation, Axis(2.0, Eigen::Vector3d::UnitX()),
                                     Axis(1.0, Eigen::Vector3d(1, 1, 0)), s.joint(3).rest_rotation};
  for (int f = 0; f <= 30; ++f) {
    const int k = std::min(f / 10, 2);
    clip.rotation(f, 3) = keys[k].slerp((f - 10.0 * k) / 10.0, keys[k + 1]);
  }
  clip.MakeContinuous();
  clip.keys[3].rotation_frames = {0, 10, 20, 30};
  clip.keys[2].rotation_frames = {15};
  return clip;
}

std::vector<Eigen::Matrix4d> InverseBindMatrices(const Skeleton& s, const std::vector<int>& joints) {
  const MotionClip rest = MotionClip::RestPose(s, 1, 30.0);
  WorldPose pose;
  ComputeWorldPose(s, rest, 0, pose);
  std::vector<Eigen::Matrix4d> out;
  for (int j : joints) {
    Eigen::Affine3d world = Eigen::Translation3d(pose.positions[j]) * pose.rotations[j];
    out.push_back(world.inverse().matrix());
  }
  return out;
}

void AddMeshes(Scene& scene) {
  Mesh hat;
  hat.name = "Hat";
  hat.attach_joint = 2;
  MeshPrimitive tri;
  tri.positions = {{-0.1f, 0.2f, 0}, {0.1f, 0.2f, 0}, {0, 0.35f, 0.05f}};
  tri.base_color = Eigen::Vector4f(0.8f, 0.1f, 0.1f, 1);
  hat.primitives.push_back(tri);
  scene.meshes.push_back(hat);

  Skin skin;
  skin.name = "body_skin";
  skin.joints = {1, 2};
  skin.inverse_bind_matrices = InverseBindMatrices(scene.skeleton, skin.joints);
  scene.skins.push_back(skin);
  Mesh body;
  body.name = "Body";
  body.skin = 0;
  MeshPrimitive strip;
  for (int row = 0; row < 3; ++row) {
    for (int side = 0; side < 2; ++side) {
      strip.positions.emplace_back(side ? 0.15f : -0.15f, 1.05f + 0.25f * row, 0.0f);
      strip.normals.emplace_back(0, 0, 1);
      strip.texcoords.emplace_back(side, row / 2.0f);
      strip.joints.push_back({0, 1, 0, 0});
      const float w = 0.1f + 0.4f * row;  // no zero weights: the writer would clean their joint slots
      strip.weights.emplace_back(1 - w, w, 0, 0);
    }
  }
  strip.indices = {0, 1, 3, 0, 3, 2, 2, 3, 5, 2, 5, 4};
  strip.base_color = Eigen::Vector4f(0.2f, 0.4f, 0.9f, 1);
  body.primitives.push_back(strip);
  scene.meshes.push_back(body);
}

const Mesh* FindMesh(const Scene& scene, const std::string& name) {
  for (const Mesh& m : scene.meshes)
    if (m.name == name) return &m;
  return nullptr;
}

void ExpectMeshesMatch(const Scene& expected, const Scene& actual) {
  ASSERT_EQ(actual.meshes.size(), expected.meshes.size());
  for (const Mesh& e : expected.meshes) {
    const Mesh* a = FindMesh(actual, e.name);
    ASSERT_NE(a, nullptr) << e.name;
    ASSERT_EQ(a->primitives.size(), e.primitives.size()) << e.name;
    ASSERT_EQ(a->skin >= 0, e.skin >= 0) << e.name;
    if (e.attach_joint >= 0) {
      ASSERT_GE(a->attach_joint, 0) << e.name;
      EXPECT_EQ(actual.skeleton.name(a->attach_joint), expected.skeleton.name(e.attach_joint));
    }
    if (e.skin >= 0) {
      const Skin& es = expected.skins[e.skin];
      const Skin& as = actual.skins[a->skin];
      ASSERT_EQ(as.joints.size(), es.joints.size());
      for (size_t k = 0; k < es.joints.size(); ++k) {
        EXPECT_EQ(actual.skeleton.name(as.joints[k]), expected.skeleton.name(es.joints[k]));
        EXPECT_LT((as.inverse_bind_matrices[k] - es.inverse_bind_matrices[k]).cwiseAbs().maxCoeff(), 1e-6);
      }
    }
    for (size_t p = 0; p < e.primitives.size(); ++p) {
      const MeshPrimitive& ep = e.primitives[p];
      const MeshPrimitive& ap = a->primitives[p];
      EXPECT_EQ(ap.positions, ep.positions) << e.name;
      EXPECT_EQ(ap.texcoords, ep.texcoords) << e.name;
      EXPECT_EQ(ap.indices, ep.indices) << e.name;
      EXPECT_EQ(ap.joints, ep.joints) << e.name;
      EXPECT_EQ(ap.base_color, ep.base_color) << e.name;
      ASSERT_EQ(ap.normals.size(), ep.normals.size());
      for (size_t v = 0; v < ep.normals.size(); ++v) EXPECT_LT((ap.normals[v] - ep.normals[v]).norm(), 1e-6f);
      ASSERT_EQ(ap.weights.size(), ep.weights.size());
      for (size_t v = 0; v < ep.weights.size(); ++v) EXPECT_LT((ap.weights[v] - ep.weights[v]).norm(), 1e-6f);
    }
  }
}

}  // namespace

std::string GltfOutputPath(const std::string& name) { return TestOutputDir("gltf") + "/" + name; }

Result<Scene> ReadGltfFile(const std::string& path, const ImportOptions& options) {
  ASSIGN_OR_RETURN(const std::string bytes, ReadFileBytes(path));
  return ReadGltf(bytes, path, options);
}

Result<std::string> WriteGltfOutput(const Scene& scene, const std::string& name) {
  const std::string path = GltfOutputPath(name);
  ASSIGN_OR_RETURN(const std::string bytes, WriteGltf(scene, LowerExtension(path) == ".glb", ExportOptions{}));
  RETURN_IF_ERROR(WriteFileAtomic(path, bytes));
  return path;
}

Scene MakeDancerScene() {
  Scene scene;
  scene.skeleton = DancerSkeleton();
  scene.clips.push_back(DanceClip(scene.skeleton));
  scene.clips.push_back(WaveClip(scene.skeleton));
  AddMeshes(scene);
  scene.source.format = "bvh";
  scene.source.path = "/data/mocap/dancer.bvh";
  scene.source.unit_name = "cm";
  scene.source.unit_scale_to_m = 0.01;
  scene.source.source_frame_time_text = "0.0083333";
  scene.source.source_frame_time_s = 0.0083333;
  return scene;
}

void ExpectScenesMatch(const Scene& expected, const Scene& actual) {
  const Skeleton& es = expected.skeleton;
  const Skeleton& as = actual.skeleton;
  ASSERT_EQ(as.num_joints(), es.num_joints());
  for (int j = 0; j < es.num_joints(); ++j) {
    const Joint& e = es.joint(j);
    const Joint& a = as.joint(j);
    EXPECT_EQ(a.name, e.name);
    EXPECT_EQ(a.parent, e.parent) << e.name;
    EXPECT_LT((a.rest_translation - e.rest_translation).norm(), 1e-12) << e.name;
    EXPECT_LT(GeodesicAngle(a.rest_rotation, e.rest_rotation), 1e-12) << e.name;
    EXPECT_LT((a.rest_scale - e.rest_scale).norm(), 1e-12) << e.name;
    EXPECT_EQ(a.bvh_channels, e.bvh_channels) << e.name;
    ASSERT_EQ(a.end_site.has_value(), e.end_site.has_value()) << e.name;
    if (e.end_site) {
      EXPECT_LT((*a.end_site - *e.end_site).norm(), 1e-12) << e.name;
    }
  }
  ASSERT_EQ(actual.clips.size(), expected.clips.size());
  for (size_t c = 0; c < expected.clips.size(); ++c) {
    const MotionClip& e = expected.clips[c];
    const MotionClip& a = actual.clips[c];
    EXPECT_EQ(a.name, e.name);
    EXPECT_EQ(a.sample_rate_hz, e.sample_rate_hz) << e.name;
    ASSERT_EQ(a.num_frames, e.num_frames) << e.name;
    EXPECT_EQ(a.translation_animated, e.translation_animated) << e.name;
    double worst_deg = 0, worst_m = 0;
    for (int j = 0; j < e.num_joints; ++j) {
      EXPECT_EQ(a.keys[j].rotation_frames, e.keys[j].rotation_frames) << e.name << " " << es.name(j);
      EXPECT_EQ(a.keys[j].translation_frames, e.keys[j].translation_frames) << e.name << " " << es.name(j);
      for (int f = 0; f < e.num_frames; ++f) {
        worst_deg = std::max(worst_deg, GeodesicAngle(a.rotation(f, j), e.rotation(f, j)) * kDegPerRad);
        worst_m = std::max(worst_m, (a.translation(f, j) - e.translation(f, j)).norm());
        if (f > 0) {
          EXPECT_GE(a.rotation(f, j).dot(a.rotation(f - 1, j)), 0.0) << "not hemisphere-continuous";
        }
      }
    }
    EXPECT_LT(worst_deg, kRotationToleranceDeg) << e.name;
    EXPECT_LT(worst_m, kTranslationToleranceM) << e.name;
  }
  EXPECT_EQ(actual.source.unit_name, expected.source.unit_name);
  EXPECT_EQ(actual.source.unit_scale_to_m, expected.source.unit_scale_to_m);
  EXPECT_EQ(actual.source.source_frame_time_text, expected.source.source_frame_time_text);
  EXPECT_EQ(actual.source.up_axis, expected.source.up_axis);
  ExpectMeshesMatch(expected, actual);
}

int SketchGltf::AddNode(const std::string& name, int parent, const std::vector<double>& translation) {
  nodes_.push_back({name, parent, translation});
  return static_cast<int>(nodes_.size()) - 1;
}

void SketchGltf::AddChannel(const std::string& animation, int node, const std::string& path,
                            const std::vector<float>& times_s, const std::vector<float>& values,
                            const std::string& interpolation) {
  channels_.push_back({animation, node, path, times_s, values, interpolation});
}

bool SketchGltf::Write(const std::string& path) const {
  tinygltf::Model model;
  std::vector<unsigned char> bytes;
  auto add = [&](const std::vector<float>& data, int type, size_t count, bool bounds) {
    tinygltf::BufferView view;
    view.buffer = 0;
    view.byteOffset = bytes.size();
    view.byteLength = data.size() * sizeof(float);
    const auto* p = reinterpret_cast<const unsigned char*>(data.data());
    bytes.insert(bytes.end(), p, p + view.byteLength);
    model.bufferViews.push_back(view);
    tinygltf::Accessor accessor;
    accessor.bufferView = static_cast<int>(model.bufferViews.size()) - 1;
    accessor.componentType = TINYGLTF_COMPONENT_TYPE_FLOAT;
    accessor.type = type;
    accessor.count = count;
    if (bounds) {
      accessor.minValues = {*std::min_element(data.begin(), data.end())};
      accessor.maxValues = {*std::max_element(data.begin(), data.end())};
    }
    model.accessors.push_back(accessor);
    return static_cast<int>(model.accessors.size()) - 1;
  };
  tinygltf::Scene scene;
  for (size_t i = 0; i < nodes_.size(); ++i) {
    tinygltf::Node node;
    node.name = nodes_[i].name;
    node.translation = nodes_[i].translation;
    model.nodes.push_back(node);
    if (nodes_[i].parent < 0) scene.nodes.push_back(static_cast<int>(i));
  }
  for (size_t i = 0; i < nodes_.size(); ++i)
    if (nodes_[i].parent >= 0) model.nodes[nodes_[i].parent].children.push_back(static_cast<int>(i));
  std::map<std::string, int> animation_index;
  for (const Channel& c : channels_) {
    if (!animation_index.count(c.animation)) {
      animation_index[c.animation] = static_cast<int>(model.animations.size());
      model.animations.emplace_back();
      model.animations.back().name = c.animation;
    }
    tinygltf::Animation& animation = model.animations[animation_index[c.animation]];
    tinygltf::AnimationSampler sampler;
    sampler.input = add(c.times, TINYGLTF_TYPE_SCALAR, c.times.size(), true);
    const int components = c.path == "rotation" ? 4 : 3;
    sampler.output = add(c.values, components == 4 ? TINYGLTF_TYPE_VEC4 : TINYGLTF_TYPE_VEC3,
                         c.values.size() / components, false);
    sampler.interpolation = c.interpolation;
    animation.samplers.push_back(sampler);
    tinygltf::AnimationChannel channel;
    channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
    channel.target_node = c.node;
    channel.target_path = c.path;
    animation.channels.push_back(channel);
  }
  tinygltf::Buffer buffer;
  buffer.data = bytes;
  model.buffers.push_back(buffer);
  model.scenes.push_back(scene);
  model.defaultScene = 0;
  model.asset.generator = "mocapfill tests (hand-made sketch)";
  tinygltf::TinyGLTF writer;
  std::ofstream out(path, std::ios::binary);
  return writer.WriteGltfSceneToStream(&model, out, true, false) && out.good();
}

}  // namespace mocapfill::testing
