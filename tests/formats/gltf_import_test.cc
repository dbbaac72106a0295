// glTF import on real files (the Assimp/Khronos skins) and hand-made sketches: skeleton
// selection, frame-rate detection, sparse keys, LINEAR/STEP/CUBICSPLINE sampling, several
// animations and selection, names.
#include <gtest/gtest.h>

#include <cmath>

#include "processing/core/rotation.h"
#include "tests/formats/gltf_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

Eigen::Quaterniond Q(const std::vector<float>& v, size_t k) {
  return Eigen::Quaterniond(v[4 * k + 3], v[4 * k], v[4 * k + 1], v[4 * k + 2]).normalized();
}

double Degrees(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b) { return GeodesicAngle(a, b) * kDegPerRad; }

// simple_skin.gltf: a skinned strip on a two-joint chain, one 5.5 s rotation animation.
void CheckSimpleSkin(const std::string& path, const std::string& out_name) {
  Result<Scene> scene = testing::ReadGltfFile(path);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const Skeleton& s = scene->skeleton;
  ASSERT_EQ(s.num_joints(), 2);  // node 0 is the skinned mesh, not a joint
  EXPECT_EQ(s.name(0), "node_1");
  EXPECT_EQ(s.name(1), "node_2");
  EXPECT_EQ(s.parent(1), 0);
  EXPECT_EQ(s.joint(0).rest_translation, Eigen::Vector3d(0, 1, 0));
  ASSERT_EQ(scene->clips.size(), 1u);
  const MotionClip& clip = scene->clips[0];
  EXPECT_EQ(clip.sample_rate_hz, 24.0);  // keys every 0.5 s: the 24 Hz grid is the lowest that fits
  EXPECT_DOUBLE_EQ(clip.duration_s(), 5.5);
  EXPECT_EQ(clip.name, "animation_0");  // unnamed in the file
  EXPECT_EQ(clip.keys[1].rotation_frames.size(), 12u);
  EXPECT_TRUE(clip.keys[0].empty());  // node_1 has no channel: missing, holds its rest pose
  // Key 2 (1.0 s, frame 24) is (0, 0, 0.707, 0.707): 90 degrees about Z.
  const Eigen::Quaterniond quarter(Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitZ()));
  EXPECT_LT(Degrees(clip.rotation(24, 1), quarter), 1e-4);
  ASSERT_EQ(scene->meshes.size(), 1u);
  ASSERT_EQ(scene->skins.size(), 1u);
  EXPECT_EQ(scene->meshes[0].primitives[0].positions.size(), 10u);
  EXPECT_EQ(scene->meshes[0].primitives[0].indices.size(), 24u);
  for (const Eigen::Vector4f& w : scene->meshes[0].primitives[0].weights) EXPECT_NEAR(w.sum(), 1.0f, 1e-6f);
  EXPECT_EQ(scene->skins[0].inverse_bind_matrices[1](1, 3), -1.0);

  Result<std::string> out = testing::WriteGltfOutput(*scene, out_name);
  ASSERT_TRUE(out.ok()) << out.status().message();
  Result<Scene> back = testing::ReadGltfFile(*out);
  ASSERT_TRUE(back.ok()) << back.status().message();
  testing::ExpectScenesMatch(*scene, *back);
}

// quad_skin.glb: a 10-bone armature under a 100x scaled, rotated matrix node; no animation.
void CheckQuadSkin(const std::string& path, const std::string& out_name) {
  Result<Scene> scene = testing::ReadGltfFile(path);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const Skeleton& s = scene->skeleton;
  ASSERT_EQ(s.num_joints(), 22);  // RootNode, Armature, 10 bones and their 10 "_end" leaves
  EXPECT_EQ(s.name(0), "RootNode");
  EXPECT_EQ(s.name(1), "Armature");
  EXPECT_EQ(s.name(2), "Bone.000");
  EXPECT_EQ(s.name(3), "Bone.000_end");
  EXPECT_EQ(s.parent(3), 2);
  EXPECT_EQ(s.Children(1).size(), 10u);
  // The Armature matrix decomposes into scale 100 and -90 degrees about X.
  EXPECT_LT((s.joint(1).rest_scale - Eigen::Vector3d(100, 100, 100)).norm(), 1e-9);
  const Eigen::Quaterniond minus_quarter_x(Eigen::AngleAxisd(-kPi / 2, Eigen::Vector3d::UnitX()));
  EXPECT_LT(Degrees(s.joint(1).rest_rotation, minus_quarter_x), 1e-3);
  EXPECT_TRUE(scene->clips.empty());
  ASSERT_EQ(scene->skins.size(), 1u);
  EXPECT_EQ(scene->skins[0].joints.size(), 10u);
  // Up to 12 influences per vertex (JOINTS_0..2): the 4 largest are kept and renormalised.
  // Vertex 0: 0.2157 (joint 5), 0.2069 (0), 0.1126 (1), 0.0901 (3), then four smaller ones.
  const MeshPrimitive& quad = scene->meshes.at(0).primitives.at(0);
  EXPECT_EQ(quad.joints[0], (std::array<std::uint16_t, 4>{5, 0, 1, 3}));
  const double top4 = 0.21567927300930023 + 0.20686699450016022 + 0.1125933825969696 + 0.09007582813501358;
  EXPECT_NEAR(quad.weights[0][0], 0.21567927300930023 / top4, 1e-6);
  for (const Eigen::Vector4f& w : quad.weights) EXPECT_NEAR(w.sum(), 1.0f, 1e-6f);
  ASSERT_EQ(scene->warnings.size(), 1u);
  EXPECT_NE(scene->warnings[0].find("more than 4 skin influences"), std::string::npos) << scene->warnings[0];
  Result<std::string> out = testing::WriteGltfOutput(*scene, out_name);
  ASSERT_TRUE(out.ok()) << out.status().message();
  Result<Scene> back = testing::ReadGltfFile(*out);
  ASSERT_TRUE(back.ok()) << back.status().message();
  testing::ExpectScenesMatch(*scene, *back);
}

TEST(GltfImport, ShippedSimpleSkin) { CheckSimpleSkin(testing::FixturePath("gltf/simple_skin.gltf"), "simple_skin.glb"); }
TEST(GltfImport, ShippedQuadSkin) { CheckQuadSkin(testing::FixturePath("gltf/quad_skin.glb"), "quad_skin.gltf"); }

TEST(GltfImport, CorpusSkins) {
  MOCAPFILL_REQUIRE_CORPUS();
  CheckSimpleSkin(testing::DataPath("assimp/simple_skin.gltf"), "corpus_simple_skin.gltf");
  CheckQuadSkin(testing::DataPath("assimp/quad_skin.glb"), "corpus_quad_skin.glb");
}

// A sketch keyed at frames 0, 8 and 16 of a 30 Hz clip (the root's translation at 0 and 16 only).
struct Sketch {
  testing::SketchGltf file;
  std::vector<float> times{0.0f, static_cast<float>(8 / 30.0), static_cast<float>(16 / 30.0)};
  std::vector<float> arm{0, 0, 0, 1, 0.5f, 0, 0, 0.8660254f, 0, 0.7071068f, 0, 0.7071068f};
};

TEST(GltfImport, SparseSketchKeepsItsKeysAndSlerpsBetween) {
  Sketch s;
  const int hips = s.file.AddNode("Hips", -1, {0, 1, 0});
  const int arm = s.file.AddNode("Arm", hips, {0.2, 0.4, 0});
  s.file.AddNode("Hand", arm, {0.3, 0, 0});
  s.file.AddChannel("sketch", arm, "rotation", s.times, s.arm);
  s.file.AddChannel("sketch", hips, "translation", {s.times[0], s.times[2]}, {0, 1, 0, 0.4f, 1, 0});
  const std::string path = testing::GltfOutputPath("sketch_sparse.gltf");
  ASSERT_TRUE(s.file.Write(path));
  Result<Scene> scene = testing::ReadGltfFile(path);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_EQ(scene->clips.size(), 1u);
  const MotionClip& clip = scene->clips[0];
  EXPECT_EQ(clip.sample_rate_hz, 30.0);
  EXPECT_EQ(clip.num_frames, 17);
  EXPECT_EQ(clip.keys[1].rotation_frames, (std::vector<int>{0, 8, 16}));
  EXPECT_TRUE(clip.keys[1].translation_frames.empty());
  EXPECT_EQ(clip.keys[0].translation_frames, (std::vector<int>{0, 16}));
  EXPECT_TRUE(clip.keys[0].rotation_frames.empty());
  EXPECT_TRUE(clip.keys[2].empty());  // the hand is missing
  EXPECT_EQ(clip.translation_animated, (std::vector<std::uint8_t>{1, 0, 0}));
  for (int f = 0; f <= 16; ++f) {
    const int k = f < 8 ? 0 : 1;
    const Eigen::Quaterniond expected = Q(s.arm, k).slerp((f - 8.0 * k) / 8.0, Q(s.arm, k + 1));
    EXPECT_LT(Degrees(clip.rotation(f, 1), expected), 1e-6) << "frame " << f;
    EXPECT_NEAR(clip.translation(f, 0).x(), 0.4 * f / 16.0, 1e-6);
  }
  EXPECT_LT(Degrees(clip.rotation(8, 1), Q(s.arm, 1)), 1e-9);  // keys land exactly on their frames
  EXPECT_EQ(clip.rotation(5, 2).coeffs(), Eigen::Quaterniond::Identity().coeffs());

  // The sketch survives our own export: the recorded keys come back.
  Result<std::string> out = testing::WriteGltfOutput(*scene, "sketch_sparse_export.glb");
  ASSERT_TRUE(out.ok());
  Result<Scene> back = testing::ReadGltfFile(*out);
  ASSERT_TRUE(back.ok()) << back.status().message();
  testing::ExpectScenesMatch(*scene, *back);
}

TEST(GltfImport, StepHoldsUntilTheNextKey) {
  Sketch s;
  const int hips = s.file.AddNode("Hips", -1);
  const int arm = s.file.AddNode("Arm", hips, {0.2, 0.4, 0});
  s.file.AddChannel("step", arm, "rotation", s.times, s.arm, "STEP");
  s.file.AddChannel("step", hips, "translation", s.times, {0, 0, 0, 1, 2, 3, -1, 0.5f, 2}, "STEP");
  const std::string path = testing::GltfOutputPath("sketch_step.gltf");
  ASSERT_TRUE(s.file.Write(path));
  Result<Scene> scene = testing::ReadGltfFile(path);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const MotionClip& clip = scene->clips[0];
  for (int f = 0; f <= 16; ++f) {
    const size_t k = f < 8 ? 0 : f < 16 ? 1 : 2;
    EXPECT_LT(Degrees(clip.rotation(f, 1), Q(s.arm, k)), 1e-9) << f;
    const Eigen::Vector3d t = k == 0 ? Eigen::Vector3d(0, 0, 0) : k == 1 ? Eigen::Vector3d(1, 2, 3) : Eigen::Vector3d(-1, 0.5, 2);
    EXPECT_EQ(clip.translation(f, 0), t) << f;
  }
}

// Hermite of the glTF spec, written out independently: tangents scale with the key spacing.
double Hermite(double v0, double b0, double v1, double a1, double s, double dt) {
  return (2 * s * s * s - 3 * s * s + 1) * v0 + (s * s * s - 2 * s * s + s) * dt * b0 +
         (-2 * s * s * s + 3 * s * s) * v1 + (s * s * s - s * s) * dt * a1;
}

TEST(GltfImport, CubicSplineFollowsTheSpecHermite) {
  Sketch s;
  const int hips = s.file.AddNode("Hips", -1);
  const int arm = s.file.AddNode("Arm", hips, {0.2, 0.4, 0});
  // Per key: in-tangent, value, out-tangent.
  const std::vector<float> t_values{0, 0, 0, 0, 0, 0, 1, 0, 0,  //
                                    -2, 1, 0, 1, 1, 0, 3, -1, 0,  //
                                    0, 0, 0, 0.5f, 0, 1, 0, 0, 0};
  std::vector<float> r_values;
  for (size_t k = 0; k < 3; ++k) {
    const std::vector<float> tangent{0.1f, -0.2f, 0.3f, 0.0f};
    r_values.insert(r_values.end(), tangent.begin(), tangent.end());
    r_values.insert(r_values.end(), s.arm.begin() + 4 * k, s.arm.begin() + 4 * k + 4);
    r_values.insert(r_values.end(), tangent.begin(), tangent.end());
  }
  s.file.AddChannel("cubic", hips, "translation", s.times, t_values, "CUBICSPLINE");
  s.file.AddChannel("cubic", arm, "rotation", s.times, r_values, "CUBICSPLINE");
  const std::string path = testing::GltfOutputPath("sketch_cubic.gltf");
  ASSERT_TRUE(s.file.Write(path));
  Result<Scene> scene = testing::ReadGltfFile(path);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  const MotionClip& clip = scene->clips[0];
  ASSERT_EQ(clip.num_frames, 17);
  for (int f = 0; f <= 16; ++f) {
    const size_t k = f < 8 ? 0 : 1;
    const double sfrac = (f - 8.0 * k) / 8.0;
    const double dt = s.times[k + 1] - s.times[k];
    for (int c = 0; c < 3; ++c) {
      const double expected = Hermite(t_values[9 * k + 3 + c], t_values[9 * k + 6 + c], t_values[9 * (k + 1) + 3 + c],
                                      t_values[9 * (k + 1) + c], sfrac, dt);
      EXPECT_NEAR(clip.translation(f, 0)[c], expected, 1e-6) << "frame " << f << " component " << c;
    }
    Eigen::Vector4d q;
    for (int c = 0; c < 4; ++c)
      q[c] = Hermite(r_values[12 * k + 4 + c], r_values[12 * k + 8 + c], r_values[12 * (k + 1) + 4 + c],
                     r_values[12 * (k + 1) + c], sfrac, dt);
    q.normalize();
    EXPECT_LT(Degrees(clip.rotation(f, 1), Eigen::Quaterniond(q[3], q[0], q[1], q[2])), 1e-4) << "frame " << f;
  }
}

TEST(GltfImport, TwoAnimationsAndSelectionByNameOrIndex) {
  Sketch s;
  const int hips = s.file.AddNode("Hips", -1);
  const int arm = s.file.AddNode("Arm", hips, {0.2, 0.4, 0});
  s.file.AddChannel("walk", arm, "rotation", s.times, s.arm);
  // 25 Hz keys: 0, 0.4 s, 1.2 s.
  s.file.AddChannel("wave", hips, "rotation", {0.0f, 0.4f, 1.2f}, s.arm);
  const std::string path = testing::GltfOutputPath("sketch_two_animations.gltf");
  ASSERT_TRUE(s.file.Write(path));

  Result<Scene> all = testing::ReadGltfFile(path);
  ASSERT_TRUE(all.ok()) << all.status().message();
  ASSERT_EQ(all->clips.size(), 2u);
  EXPECT_EQ(all->clips[0].name, "walk");
  EXPECT_EQ(all->clips[0].sample_rate_hz, 30.0);
  EXPECT_EQ(all->clips[1].name, "wave");
  EXPECT_EQ(all->clips[1].sample_rate_hz, 25.0);
  EXPECT_EQ(all->clips[1].num_frames, 31);
  EXPECT_EQ(all->clips[1].keys[0].rotation_frames, (std::vector<int>{0, 10, 30}));

  for (const std::string selection : {"wave", "1"}) {
    ImportOptions options;
    options.animation = selection;
    Result<Scene> one = testing::ReadGltfFile(path, options);
    ASSERT_TRUE(one.ok()) << one.status().message();
    ASSERT_EQ(one->clips.size(), 1u);
    EXPECT_EQ(one->clips[0].name, "wave");
    EXPECT_EQ(one->skeleton.num_joints(), 2);  // the skeleton does not depend on the selection
  }
  ImportOptions missing;
  missing.animation = "run";
  Result<Scene> none = testing::ReadGltfFile(path, missing);
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.status().code(), ErrorCode::kInvalidArgument);
  EXPECT_NE(none.status().message().find("'walk' (0), 'wave' (1)"), std::string::npos) << none.status().message();

  Result<std::string> out = testing::WriteGltfOutput(*all, "sketch_two_animations_export.glb");
  ASSERT_TRUE(out.ok());
  Result<Scene> back = testing::ReadGltfFile(*out);
  ASSERT_TRUE(back.ok()) << back.status().message();
  testing::ExpectScenesMatch(*all, *back);
}

TEST(GltfImport, OffGridKeysFallBackToThirtyHertzWithAWarning) {
  Sketch s;
  const int hips = s.file.AddNode("Hips", -1);
  s.file.AddChannel("odd", hips, "rotation", {0.0f, 0.0123f, 0.5f}, s.arm);
  const std::string path = testing::GltfOutputPath("sketch_off_grid.gltf");
  ASSERT_TRUE(s.file.Write(path));
  Result<Scene> scene = testing::ReadGltfFile(path);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->clips[0].sample_rate_hz, 30.0);
  EXPECT_EQ(scene->clips[0].num_frames, 16);
  ASSERT_EQ(scene->warnings.size(), 1u);
  EXPECT_NE(scene->warnings[0].find("30 Hz"), std::string::npos);
  ImportOptions strict;
  strict.strict = true;
  EXPECT_EQ(testing::ReadGltfFile(path, strict).status().code(), ErrorCode::kInvalidData);
}

TEST(GltfImport, ScaleAnimationIsIgnoredWithAWarning) {
  Sketch s;
  const int hips = s.file.AddNode("Hips", -1);
  const int arm = s.file.AddNode("Arm", hips, {0.2, 0.4, 0});
  s.file.AddChannel("grow", arm, "rotation", s.times, s.arm);
  s.file.AddChannel("grow", hips, "scale", s.times, {1, 1, 1, 1, 1, 1, 1, 1, 1});
  s.file.AddChannel("grow", arm, "scale", s.times, {1, 1, 1, 2, 2, 2, 1, 1, 1});
  const std::string path = testing::GltfOutputPath("sketch_scale.gltf");
  ASSERT_TRUE(s.file.Write(path));
  Result<Scene> scene = testing::ReadGltfFile(path);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  ASSERT_EQ(scene->warnings.size(), 1u);  // the unit scale on Hips is not worth a warning
  EXPECT_NE(scene->warnings[0].find("scale animation of joint 'Arm' ignored"), std::string::npos);
  EXPECT_EQ(scene->skeleton.joint(1).rest_scale, Eigen::Vector3d::Ones());
}

TEST(GltfImport, DuplicateAndMissingNamesBecomeUnique) {
  Sketch s;
  const int root = s.file.AddNode("Bone", -1);
  const int child = s.file.AddNode("Bone", root, {0, 1, 0});
  s.file.AddNode("", child, {0, 1, 0});
  s.file.AddChannel("bend", child, "rotation", s.times, s.arm);
  const std::string path = testing::GltfOutputPath("sketch_names.gltf");
  ASSERT_TRUE(s.file.Write(path));
  Result<Scene> scene = testing::ReadGltfFile(path);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->skeleton.name(0), "Bone");
  EXPECT_EQ(scene->skeleton.name(1), "Bone_2");
  EXPECT_EQ(scene->skeleton.name(2), "node_2");
  ASSERT_FALSE(scene->warnings.empty());
  EXPECT_NE(scene->warnings[0].find("duplicate name 'Bone'"), std::string::npos);
}

}  // namespace
}  // namespace mocapfill
