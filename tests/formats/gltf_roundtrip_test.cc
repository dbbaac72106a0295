// glTF export and re-import: exact skeleton, clips within float32 tolerance, keys, meshes,
// skins, provenance; deterministic bytes; structural rules of a validator-clean file.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "formats/file_io.h"
#include "formats/gltf/glb_container.h"
#include "formats/gltf/gltf_writer.h"
#include "processing/core/rotation.h"
#include "tests/formats/gltf_test_support.h"

namespace mocapfill {
namespace {

using nlohmann::json;

json JsonOf(const std::string& bytes, bool binary) {
  if (!binary) return json::parse(bytes);
  auto parts = gltf_internal::ParseGlbContainer(bytes);
  EXPECT_TRUE(parts.ok()) << parts.status().message();
  return parts.ok() ? json::parse(parts->json) : json();
}

class GltfRoundTrip : public ::testing::TestWithParam<const char*> {};

TEST_P(GltfRoundTrip, DancerSceneComesBackExactly) {
  const Scene scene = testing::MakeDancerScene();
  const std::string name = std::string("dancer") + GetParam();
  Result<std::string> path = testing::WriteGltfOutput(scene, name);
  ASSERT_TRUE(path.ok()) << path.status().message();
  Result<Scene> back = testing::ReadGltfFile(*path);
  ASSERT_TRUE(back.ok()) << back.status().message();
  EXPECT_EQ(back->source.format, std::string(GetParam()) == ".glb" ? "glb" : "gltf");
  EXPECT_TRUE(back->warnings.empty()) << back->warnings.front();
  testing::ExpectScenesMatch(scene, *back);
}

TEST_P(GltfRoundTrip, SameSceneGivesSameBytes) {
  const Scene scene = testing::MakeDancerScene();
  const bool binary = std::string(GetParam()) == ".glb";
  Result<std::string> a = WriteGltf(scene, binary, {});
  Result<std::string> b = WriteGltf(scene, binary, {});
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(*a, *b);
  // The source path's folder must not leak into the file (machine-independent output).
  EXPECT_EQ(a->find("/data/mocap"), std::string::npos);
}

TEST_P(GltfRoundTrip, ReExportOfReImportIsStable) {
  // glTF -> Scene -> glTF -> Scene must not drift: the second import equals the first.
  const Scene scene = testing::MakeDancerScene();
  const std::string ext = GetParam();
  Result<std::string> first = testing::WriteGltfOutput(scene, "dancer_pass1" + ext);
  ASSERT_TRUE(first.ok());
  Result<Scene> once = testing::ReadGltfFile(*first);
  ASSERT_TRUE(once.ok()) << once.status().message();
  Result<std::string> second = testing::WriteGltfOutput(*once, "dancer_pass2" + ext);
  ASSERT_TRUE(second.ok());
  Result<Scene> twice = testing::ReadGltfFile(*second);
  ASSERT_TRUE(twice.ok()) << twice.status().message();
  testing::ExpectScenesMatch(*once, *twice);
}

INSTANTIATE_TEST_SUITE_P(Containers, GltfRoundTrip, ::testing::Values(".glb", ".gltf"),
                         [](const ::testing::TestParamInfo<const char*>& param) { return std::string(param.param + 1); });

TEST(GltfWriter, FollowsTheExporterChecklist) {
  const Scene scene = testing::MakeDancerScene();
  for (const bool binary : {true, false}) {
    Result<std::string> bytes = WriteGltf(scene, binary, {});
    ASSERT_TRUE(bytes.ok()) << bytes.status().message();
    const json doc = JsonOf(*bytes, binary);
    EXPECT_EQ(doc["asset"]["generator"], "mocapfill");
    EXPECT_EQ(doc["asset"]["version"], "2.0");
    const json& info = doc["asset"]["extras"]["mocapfill"];
    EXPECT_EQ(info["source_format"], "bvh");
    EXPECT_EQ(info["source_file"], "dancer.bvh");
    EXPECT_EQ(info["unit_name"], "cm");
    EXPECT_EQ(info["metres_per_unit"], 0.01);
    EXPECT_EQ(info["source_frame_time_text"], "0.0083333");
    EXPECT_EQ(info["up_axis_conversion"], "none");
    ASSERT_EQ(info["clips"].size(), 2u);
    EXPECT_EQ(info["clips"][0]["sample_rate_hz"], 120.0);
    EXPECT_FALSE(info["clips"][0].contains("keys"));  // fully keyed: nothing to record
    EXPECT_EQ(info["clips"][1]["keys"]["Left Arm"]["rotation"], json::parse("[[0,0],[10,10],[20,20],[30,30]]"));

    // Joint j is node j, named after it, with TRS and no matrix; BVH layout in extras.
    const json& nodes = doc["nodes"];
    for (int j = 0; j < scene.skeleton.num_joints(); ++j) {
      EXPECT_EQ(nodes[j]["name"], scene.skeleton.name(j));
      EXPECT_FALSE(nodes[j].contains("matrix"));
    }
    EXPECT_EQ(nodes[0]["extras"]["bvh_channels"].size(), 6u);
    EXPECT_EQ(nodes[2]["extras"]["bvh_end_site"], json::parse("[0.0, 0.12, 0.0]"));

    const json& accessors = doc["accessors"];
    ASSERT_EQ(doc["animations"].size(), 2u);
    for (const json& animation : doc["animations"]) {
      // One shared time accessor, LINEAR, rotation for every joint, translation only where animated.
      std::set<int> inputs;
      int rotations = 0, translations = 0;
      for (const json& s : animation["samplers"]) {
        inputs.insert(s["input"].get<int>());
        EXPECT_EQ(s["interpolation"], "LINEAR");
      }
      for (const json& c : animation["channels"]) {
        rotations += c["target"]["path"] == "rotation";
        translations += c["target"]["path"] == "translation";
      }
      ASSERT_EQ(inputs.size(), 1u);
      const json& times = accessors[*inputs.begin()];
      EXPECT_EQ(times["min"][0], 0.0);
      EXPECT_TRUE(times.contains("max"));
      EXPECT_EQ(rotations, scene.skeleton.num_joints());
      EXPECT_EQ(translations, animation["name"] == "dance" ? 2 : 0);
    }
    EXPECT_EQ(accessors[doc["animations"][0]["samplers"][0]["input"].get<int>()]["max"][0].get<double>(),
              static_cast<double>(static_cast<float>(96 / 120.0)));
    for (const json& view : doc["bufferViews"]) {
      EXPECT_FALSE(view.contains("byteStride"));
      EXPECT_EQ(view.value("byteOffset", 0) % 4, 0);
    }
    // Skinned mesh at the scene root without a transform; skin skeleton = common root (Spine).
    ASSERT_EQ(doc["skins"].size(), 1u);
    EXPECT_EQ(doc["skins"][0]["skeleton"], 1);
    for (const json& node : nodes) {
      if (!node.contains("skin")) continue;
      EXPECT_FALSE(node.contains("translation") || node.contains("rotation") || node.contains("scale"));
      bool at_root = false;
      for (const json& r : doc["scenes"][0]["nodes"]) at_root = at_root || nodes[r.get<int>()] == node;
      EXPECT_TRUE(at_root);
    }
  }
}

TEST(GltfWriter, WeightsAreCleanedForTheValidator) {
  Scene scene = testing::MakeDancerScene();
  MeshPrimitive& p = scene.meshes[1].primitives[0];
  p.weights[0] = Eigen::Vector4f(0.6f, 0.6f, 0, 0);  // sums to 1.2 (as FBX files often do)
  p.joints[0] = {1, 1, 0, 0};                        // the same joint twice
  p.joints[1] = {1, 0, 1, 0};                        // joint 1 with zero weight in slot 2
  p.weights[1] = Eigen::Vector4f(1, 0, 0, 0);
  Result<std::string> path = testing::WriteGltfOutput(scene, "dancer_dirty_weights.glb");
  ASSERT_TRUE(path.ok());
  Result<Scene> back = testing::ReadGltfFile(*path);
  ASSERT_TRUE(back.ok()) << back.status().message();
  const MeshPrimitive* q = nullptr;
  for (const Mesh& m : back->meshes)
    if (m.name == "Body") q = &m.primitives[0];
  ASSERT_NE(q, nullptr);
  EXPECT_EQ(q->joints[0], (std::array<std::uint16_t, 4>{1, 0, 0, 0}));
  EXPECT_FLOAT_EQ(q->weights[0][0], 1.0f);
  EXPECT_EQ(q->joints[1], (std::array<std::uint16_t, 4>{1, 0, 0, 0}));
}

TEST(GltfWriter, RefusesAnEmptySkeleton) {
  Result<std::string> bytes = WriteGltf(Scene{}, true, {});
  ASSERT_FALSE(bytes.ok());
  EXPECT_EQ(bytes.status().code(), ErrorCode::kInvalidArgument);
}

TEST(GltfReader, UnitAndAxisOptionsApplyToTheWholeScene) {
  const Scene scene = testing::MakeDancerScene();
  Result<std::string> path = testing::WriteGltfOutput(scene, "dancer_units.glb");
  ASSERT_TRUE(path.ok());
  ImportOptions cm;
  cm.unit = "cm";
  Result<Scene> small = testing::ReadGltfFile(*path, cm);
  ASSERT_TRUE(small.ok()) << small.status().message();
  EXPECT_NEAR(small->skeleton.joint(0).rest_translation.y(), 0.0095, 1e-12);
  EXPECT_NEAR(small->clips[0].translation(96, 0).z(), 0.012 * 96 / 120.0, 1e-8);
  EXPECT_EQ(small->source.unit_name, "cm");

  ImportOptions zup;
  zup.up = "z";
  Result<Scene> turned = testing::ReadGltfFile(*path, zup);
  ASSERT_TRUE(turned.ok()) << turned.status().message();
  // (x, y, z) Z-up becomes (x, z, -y) Y-up: the hips' 0.95 m height moves to -z.
  EXPECT_NEAR(turned->skeleton.joint(0).rest_translation.z(), -0.95, 1e-12);
  EXPECT_EQ(turned->source.up_axis, "z");

  ImportOptions bad_rate;
  bad_rate.rate_hz = -5;
  EXPECT_EQ(testing::ReadGltfFile(*path, bad_rate).status().code(), ErrorCode::kInvalidArgument);
}

TEST(GltfReader, RateOptionResamplesAndDropsRecordedKeys) {
  const Scene scene = testing::MakeDancerScene();
  Result<std::string> path = testing::WriteGltfOutput(scene, "dancer_resample.gltf");
  ASSERT_TRUE(path.ok());
  ImportOptions options;
  options.rate_hz = 60;
  Result<Scene> back = testing::ReadGltfFile(*path, options);
  ASSERT_TRUE(back.ok()) << back.status().message();
  const MotionClip& dance = back->clips[0];
  EXPECT_EQ(dance.sample_rate_hz, 60.0);
  EXPECT_EQ(dance.num_frames, 49);  // 0.8 s
  // Every other 120 Hz frame is a 60 Hz frame: the samples agree with the source.
  for (int f = 0; f < dance.num_frames; ++f)
    EXPECT_LT(GeodesicAngle(dance.rotation(f, 0), scene.clips[0].rotation(2 * f, 0)) * kDegPerRad, 1e-4);
  // At another rate the recorded sketch keys no longer apply: keys are where the file's
  // 30 Hz key times fall on the 60 Hz grid, for every exported channel.
  const MotionClip& wave = back->clips[1];
  EXPECT_EQ(wave.num_frames, 61);
  ASSERT_EQ(wave.keys[3].rotation_frames.size(), 31u);
  EXPECT_EQ(wave.keys[3].rotation_frames[1], 2);
  EXPECT_EQ(wave.keys[0].rotation_frames.size(), 31u);
}

}  // namespace
}  // namespace mocapfill
