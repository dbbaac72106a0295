// FBX import through Assimp on the shipped fixture fbx/animation_with_skeleton.fbx (Assimp's
// test model, Blender 2.90 export). Expected numbers come from `assimp info -v` and
// `assimp dump` on the same file: 21 nodes (RootNode, Cube, Light, Camera, Armature and
// 16 bone nodes), one mesh of 2464 vertices / 2112 triangles with 13 bones, one animation
// 'Armature|ArmatureAction' of 20 ticks at 24 ticks/s with 15 channels, UnitScaleFactor 1
// (cm), Y up, scene bounding box (-3642.014, -91.667, -91.667) .. (3479.132, 91.667, 91.667) cm.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>

#include "formats/assimp/assimp_reader.h"
#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

const std::string kFbx = "fbx/animation_with_skeleton.fbx";

Scene ImportFixture(const ImportOptions& options = {}) {
  Result<Scene> scene = ReadWithAssimp(testing::FixturePath(kFbx), options);
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  return scene.ok() ? std::move(scene).value() : Scene{};
}

std::string ParentName(const Skeleton& s, int j) { return s.parent(j) == kNoParent ? "" : s.name(s.parent(j)); }

TEST(AssimpFbx, JointsAreTheArmatureAndItsBonesWithoutHelperNodes) {
  const Scene scene = ImportFixture();
  const Skeleton& s = scene.skeleton;
  // Parent of every joint, as in `assimp info` (RootNode, Cube, Light, Camera are not joints).
  const std::map<std::string, std::string> expected_parent = {
      {"Armature", ""},          {"Bone", "Armature"},      {"Bone.001", "Bone"},      {"Bone.002", "Bone.001"},
      {"Bone.003", "Bone.002"},  {"Bone.004", "Bone.003"},  {"Bone.005", "Bone.004"},  {"Bone.006", "Bone.005"},
      {"Bone.006_end", "Bone.006"}, {"Bone.007", "Armature"}, {"Bone.008", "Bone.007"}, {"Bone.009", "Bone.008"},
      {"Bone.010", "Bone.009"},  {"Bone.011", "Bone.010"},  {"Bone.012", "Bone.011"},  {"Bone.013", "Bone.012"},
      {"Bone.013_end", "Bone.013"}};
  ASSERT_EQ(s.num_joints(), 17);
  for (int j = 0; j < s.num_joints(); ++j) {
    EXPECT_EQ(s.name(j).find("$AssimpFbx$"), std::string::npos) << s.name(j);
    ASSERT_TRUE(expected_parent.count(s.name(j))) << "unexpected joint " << s.name(j);
    EXPECT_EQ(ParentName(s, j), expected_parent.at(s.name(j))) << s.name(j);
    EXPECT_LT(s.parent(j), j);
  }
  EXPECT_EQ(s.Roots(), std::vector<int>{0});
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
}

TEST(AssimpFbx, RestPoseIsInMetresWithTheArmatureScaleBakedIn) {
  const Scene scene = ImportFixture();
  const Skeleton& s = scene.skeleton;
  EXPECT_EQ(scene.source.format, "fbx");
  EXPECT_EQ(scene.source.unit_name, "cm");
  EXPECT_DOUBLE_EQ(scene.source.unit_scale_to_m, 0.01);
  EXPECT_FALSE(scene.source.unit_detected);
  EXPECT_EQ(scene.source.up_axis, "y");
  // Armature: T (-3614.023926, 0, 0) cm, R -90 deg about X, S 100 (baked into its children).
  const Joint& armature = s.joint(*s.Find("Armature"));
  EXPECT_NEAR(armature.rest_translation.x(), -36.14023926, 1e-7);
  EXPECT_NEAR(armature.rest_translation.tail<2>().norm(), 0.0, 1e-9);
  EXPECT_NEAR(GeodesicAngle(armature.rest_rotation, Eigen::Quaterniond(Eigen::AngleAxisd(-kPi / 2, Eigen::Vector3d::UnitX()))),
              0.0, 1e-6);
  for (const Joint& joint : s.joints()) EXPECT_TRUE(joint.rest_scale.isApprox(Eigen::Vector3d::Ones(), 1e-6)) << joint.name;
  // Bone.001: T (0, 4.469264, 0) in armature units of 100 cm -> 4.469264 m.
  EXPECT_NEAR(s.joint(*s.Find("Bone.001")).rest_translation.y(), 4.469264, 1e-5);
  EXPECT_NEAR(s.joint(*s.Find("Bone.013_end")).rest_translation.y(), 7.090999, 1e-5);
}

TEST(AssimpFbx, AnimationDurationRateAndKeys) {
  const Scene scene = ImportFixture();
  const Skeleton& s = scene.skeleton;
  ASSERT_EQ(scene.clips.size(), 1u);
  const MotionClip& clip = scene.clips[0];
  EXPECT_EQ(clip.name, "Armature|ArmatureAction");
  // 20 ticks at 24 ticks/s, keys on whole ticks: 24 Hz, 21 frames, 0.8333 s.
  EXPECT_DOUBLE_EQ(clip.sample_rate_hz, 24.0);
  EXPECT_EQ(clip.num_frames, 21);
  EXPECT_NEAR(clip.duration_s(), 20.0 / 24.0, 1e-12);
  ASSERT_TRUE(clip.Validate(s).ok());
  // 15 channels: the armature and 14 bones; end joints are not animated.
  int keyed = 0;
  for (int j = 0; j < s.num_joints(); ++j) keyed += !clip.keys[j].rotation_frames.empty();
  EXPECT_EQ(keyed, 15);
  EXPECT_TRUE(clip.keys[*s.Find("Bone.006_end")].empty());
  EXPECT_EQ(clip.keys[*s.Find("Bone.003")].rotation_frames, (std::vector<int>{0, 20}));
  // Bone.005 has keys on ticks 0..12 and 20.
  std::vector<int> expected;
  for (int f = 0; f <= 12; ++f) expected.push_back(f);
  expected.push_back(20);
  EXPECT_EQ(clip.keys[*s.Find("Bone.005")].rotation_frames, expected);
  // Bone.006's translation moves by 2e-6 armature units (2 um) between its two keys.
  EXPECT_EQ(clip.translation_animated[*s.Find("Bone.006")], 1);
  EXPECT_EQ(clip.keys[*s.Find("Bone.006")].translation_frames, (std::vector<int>{0, 20}));
  EXPECT_EQ(clip.translation_animated[*s.Find("Armature")], 0);
}

TEST(AssimpFbx, SampledRotationsMatchTheKeys) {
  const Scene scene = ImportFixture();
  const MotionClip& clip = scene.clips.at(0);
  const int bone5 = *scene.skeleton.Find("Bone.005");
  // Rotation keys of Bone.005 from `assimp dump` (w, x, y, z), tick = frame here.
  const std::map<int, Eigen::Quaterniond> keys = {{0, {0.999967, 0, 0, -0.008087}},
                                                  {6, {0.987597, 0, 0, 0.157009}},
                                                  {12, {0.948157, 0, 0, 0.317802}},
                                                  {16, {0.948157, 0, 0, 0.317802}},  // held between ticks 12 and 20
                                                  {20, {0.948157, 0, 0, 0.317802}}};
  for (const auto& [frame, q] : keys)
    EXPECT_LT(GeodesicAngle(clip.rotation(frame, bone5), q.normalized()), 2e-5) << "frame " << frame;
  for (int f = 1; f < clip.num_frames; ++f)
    for (int j = 0; j < clip.num_joints; ++j) EXPECT_GE(clip.rotation(f, j).dot(clip.rotation(f - 1, j)), 0.0);
}

TEST(AssimpFbx, SkinWeightsAndInverseBindMatrices) {
  const Scene scene = ImportFixture();
  const Skeleton& s = scene.skeleton;
  ASSERT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.skins.size(), 1u);
  const Mesh& mesh = scene.meshes[0];
  const Skin& skin = scene.skins[0];
  EXPECT_EQ(mesh.skin, 0);
  ASSERT_EQ(mesh.primitives.size(), 1u);
  const MeshPrimitive& prim = mesh.primitives[0];
  EXPECT_EQ(prim.positions.size(), 2464u);
  EXPECT_EQ(prim.indices.size(), 2112u * 3);
  EXPECT_EQ(prim.normals.size(), prim.positions.size());
  EXPECT_EQ(prim.texcoords.size(), prim.positions.size());
  EXPECT_TRUE(prim.base_color.isApprox(Eigen::Vector4f(0.8f, 0.8f, 0.8f, 1.0f), 1e-5f));
  // 13 bones: every bone but Bone.001, which weights no vertex.
  ASSERT_EQ(skin.joints.size(), 13u);
  ASSERT_EQ(skin.inverse_bind_matrices.size(), 13u);
  for (size_t k = 0; k < skin.joints.size(); ++k) {
    ASSERT_GE(skin.joints[k], 0);
    ASSERT_LT(skin.joints[k], s.num_joints());
    EXPECT_EQ(s.name(skin.joints[k]).rfind("Bone", 0), 0u);
    EXPECT_NE(s.name(skin.joints[k]), "Bone.001");
    const Eigen::Matrix4d& ibm = skin.inverse_bind_matrices[k];
    EXPECT_TRUE(ibm.allFinite());
    EXPECT_TRUE(ibm.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1)));
  }
  ASSERT_EQ(prim.weights.size(), prim.positions.size());
  ASSERT_EQ(prim.joints.size(), prim.positions.size());
  for (size_t v = 0; v < prim.weights.size(); ++v) {
    const Eigen::Vector4f& w = prim.weights[v];
    EXPECT_NEAR(static_cast<double>(w.sum()), 1.0, 1e-6) << "vertex " << v;
    for (int i = 0; i < 4; ++i) {
      EXPECT_GE(w[i], 0.0f);
      EXPECT_LT(prim.joints[v][i], skin.joints.size());
      if (w[i] == 0.0f) {
        EXPECT_EQ(prim.joints[v][i], 0) << "unused slot of vertex " << v;
      }
    }
  }
}

TEST(AssimpFbx, BindPoseBoneLengthsMatchTheSkeleton) {
  // The inverse bind matrices give each bone's bind-pose placement; bones are rigid, so the
  // distance between a bone and its parent at bind time equals the rest offset length. This
  // checks that IBMs, rest offsets and the unit/scale conversion agree.
  const Scene scene = ImportFixture();
  const Skeleton& s = scene.skeleton;
  const Skin& skin = scene.skins.at(0);
  std::map<int, Eigen::Vector3d> bind_position;
  for (size_t k = 0; k < skin.joints.size(); ++k)
    bind_position[skin.joints[k]] = skin.inverse_bind_matrices[k].inverse().block<3, 1>(0, 3);
  int checked = 0;
  for (const auto& [j, p] : bind_position) {
    const auto parent = bind_position.find(s.parent(j));
    if (parent == bind_position.end()) continue;
    EXPECT_NEAR((p - parent->second).norm(), s.joint(j).rest_translation.norm(), 1e-5) << s.name(j);
    ++checked;
  }
  EXPECT_EQ(checked, 10);  // 13 skin joints minus Bone, Bone.007 (parent Armature) and Bone.002 (parent Bone.001)
}

TEST(AssimpFbx, SkinnedMeshIsInMetresWithTheBoundsAssimpReports) {
  const Scene scene = ImportFixture();
  Eigen::Vector3f lo = Eigen::Vector3f::Constant(1e30f), hi = -lo;
  for (const Eigen::Vector3f& p : scene.meshes.at(0).primitives.at(0).positions) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  EXPECT_TRUE(lo.isApprox(Eigen::Vector3f(-36.42014160f, -0.91666702f, -0.91666672f), 1e-5f)) << lo.transpose();
  EXPECT_TRUE(hi.isApprox(Eigen::Vector3f(34.79132324f, 0.91666679f, 0.91666672f), 1e-5f)) << hi.transpose();
}

TEST(AssimpFbx, ImportIsDeterministic) {
  const Scene a = ImportFixture(), b = ImportFixture();
  ASSERT_EQ(a.skeleton.num_joints(), b.skeleton.num_joints());
  for (int j = 0; j < a.skeleton.num_joints(); ++j) {
    EXPECT_EQ(a.skeleton.name(j), b.skeleton.name(j));
    EXPECT_EQ(a.skeleton.joint(j).rest_translation, b.skeleton.joint(j).rest_translation);
    EXPECT_EQ(a.skeleton.joint(j).rest_rotation.coeffs(), b.skeleton.joint(j).rest_rotation.coeffs());
  }
  ASSERT_EQ(a.clips.size(), b.clips.size());
  for (size_t c = 0; c < a.clips.size(); ++c) {
    for (size_t i = 0; i < a.clips[c].rotations.size(); ++i) {
      EXPECT_EQ(a.clips[c].rotations[i].coeffs(), b.clips[c].rotations[i].coeffs());
      EXPECT_EQ(a.clips[c].translations[i], b.clips[c].translations[i]);
    }
  }
  const MeshPrimitive &pa = a.meshes.at(0).primitives.at(0), &pb = b.meshes.at(0).primitives.at(0);
  EXPECT_EQ(pa.positions, pb.positions);
  EXPECT_EQ(pa.indices, pb.indices);
  EXPECT_EQ(pa.weights, pb.weights);
  EXPECT_EQ(pa.joints, pb.joints);
  EXPECT_EQ(a.skins.at(0).inverse_bind_matrices, b.skins.at(0).inverse_bind_matrices);
}

TEST(AssimpFbx, OptionsOverrideUnitUpAxisRateAndPickAnimations) {
  ImportOptions metres;
  metres.unit = "m";
  EXPECT_NEAR(ImportFixture(metres).skeleton.joint(0).rest_translation.x(), -3614.023926, 1e-4);

  ImportOptions z_up;
  z_up.up = "z";
  const Scene turned = ImportFixture(z_up);
  EXPECT_EQ(turned.source.up_axis, "z");
  EXPECT_NEAR(GeodesicAngle(turned.skeleton.joint(0).rest_rotation, ImportFixture().skeleton.joint(0).rest_rotation),
              kPi / 2, 1e-9);

  ImportOptions at_30;
  at_30.rate_hz = 30.0;
  const Scene resampled = ImportFixture(at_30);
  EXPECT_EQ(resampled.clips.at(0).num_frames, 26);  // 0.8333 s at 30 Hz
  EXPECT_NEAR(resampled.clips.at(0).duration_s(), 20.0 / 24.0, 1e-12);

  ImportOptions by_name, by_index, unknown;
  by_name.animation = "Armature|ArmatureAction";
  by_index.animation = "0";
  unknown.animation = "Walk";
  EXPECT_EQ(ImportFixture(by_name).clips.size(), 1u);
  EXPECT_EQ(ImportFixture(by_index).clips.size(), 1u);
  const Result<Scene> missing = ReadWithAssimp(testing::FixturePath(kFbx), unknown);
  ASSERT_FALSE(missing.ok());
  EXPECT_EQ(missing.status().code(), ErrorCode::kInvalidArgument);
  EXPECT_NE(missing.status().message().find("'Armature|ArmatureAction'"), std::string::npos) << missing.status().message();
  EXPECT_NE(missing.status().message().find("'Walk'"), std::string::npos);

  ImportOptions bad_unit;
  bad_unit.unit = "furlong";
  EXPECT_EQ(ReadWithAssimp(testing::FixturePath(kFbx), bad_unit).status().code(), ErrorCode::kInvalidArgument);
}

// fbx/pivot_chain.fbx (hand-written ASCII FBX): Hips at T (0, 100, 0) cm with RotationPivot
// (0, 10, 0), PreRotation 90 deg about Z and Lcl Rotation about X keyed 0, 45, 90 deg at
// 0, 0.5, 1 s; Spine at (0, 20, 0) below it. By the FBX transform formula
// T * Rp * Rpre * R * Rp^-1 the Hips origin is (0, 110, 0) + Rpre * R * (0, -10, 0) and the
// Spine is at (0, 110, 0) + Rpre * R * (0, 10, 0) (cm).
TEST(AssimpFbxPivots, PivotHelpersAreFoldedIntoTheJointAndItsAnimation) {
  const Result<Scene> imported = ReadWithAssimp(testing::FixturePath("fbx/pivot_chain.fbx"), {});
  ASSERT_TRUE(imported.ok()) << imported.status().message();
  const Scene& scene = *imported;
  EXPECT_TRUE(scene.warnings.empty()) << scene.warnings.front();
  const Skeleton& s = scene.skeleton;
  ASSERT_EQ(s.num_joints(), 2);  // no "Hips_$AssimpFbx$_RotationPivot" and friends
  EXPECT_EQ(s.name(0), "Hips");
  EXPECT_EQ(s.name(1), "Spine");
  EXPECT_EQ(s.parent(1), 0);
  ASSERT_EQ(scene.clips.size(), 1u);
  const MotionClip& clip = scene.clips[0];
  EXPECT_EQ(clip.name, "Take 001");
  EXPECT_DOUBLE_EQ(clip.sample_rate_hz, 24.0);
  EXPECT_EQ(clip.num_frames, 25);
  EXPECT_EQ(clip.keys[0].rotation_frames, (std::vector<int>{0, 12, 24}));
  // The pivot makes the rotation keys move the Hips origin too.
  EXPECT_EQ(clip.keys[0].translation_frames, (std::vector<int>{0, 12, 24}));
  EXPECT_EQ(clip.translation_animated[0], 1);
  EXPECT_TRUE(clip.keys[1].empty());

  const double h = 0.1 * std::sqrt(0.5);
  const std::map<int, std::pair<Eigen::Vector3d, Eigen::Vector3d>> expected = {
      {0, {{0.1, 1.1, 0.0}, {-0.1, 1.1, 0.0}}},
      {12, {{h, 1.1, -h}, {-h, 1.1, h}}},
      {24, {{0.0, 1.1, -0.1}, {0.0, 1.1, 0.1}}}};
  WorldPose pose;
  for (const auto& [frame, hips_spine] : expected) {
    ComputeWorldPose(s, clip, frame, pose);
    EXPECT_LT((pose.positions[0] - hips_spine.first).norm(), 1e-6) << "Hips, frame " << frame;
    EXPECT_LT((pose.positions[1] - hips_spine.second).norm(), 1e-6) << "Spine, frame " << frame;
  }
}

// The same file with its GlobalSettings edited: Z up and metres (UnitScaleFactor 100).
TEST(AssimpFbxPivots, UpAxisAndUnitComeFromTheGlobalSettings) {
  std::ifstream in(testing::FixturePath("fbx/pivot_chain.fbx"));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const auto replace = [&text](const std::string& from, const std::string& to) {
    const size_t at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
  };
  replace(R"(P: "UpAxis", "int", "Integer", "",1)", R"(P: "UpAxis", "int", "Integer", "",2)");
  replace(R"(P: "UnitScaleFactor", "double", "Number", "",1)", R"(P: "UnitScaleFactor", "double", "Number", "",100)");
  const std::string path = testing::ScratchDir("assimp_global_settings") + "/z_up_metres.fbx";
  std::ofstream(path) << text;
  const Result<Scene> scene = ReadWithAssimp(path, {});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->source.up_axis, "z");
  EXPECT_EQ(scene->source.unit_name, "m");
  EXPECT_DOUBLE_EQ(scene->source.unit_scale_to_m, 1.0);
  // Hips rests at (10, 110, 0) file units = metres; Z up (x, y, z) becomes Y up (x, z, -y).
  EXPECT_LT((scene->skeleton.joint(0).rest_translation - Eigen::Vector3d(10.0, 0.0, -110.0)).norm(), 1e-5)
      << scene->skeleton.joint(0).rest_translation.transpose();  // Assimp keeps float matrices
  WorldPose pose;
  ComputeWorldPose(scene->skeleton, scene->clips.at(0), 24, pose);
  EXPECT_LT((pose.positions[1] - Eigen::Vector3d(0.0, 10.0, -110.0)).norm(), 1e-5);  // Spine at (0, 110, 10)
}

// Other Assimp formats, from the shared corpus: the Khronos tutorial skins as Assimp reads
// them (glTF is metres by definition, so no unit guessing).
TEST(AssimpCorpus, SimpleSkinGltfThroughAssimp) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Result<Scene> scene = ReadWithAssimp(testing::DataPath("assimp/simple_skin.gltf"), {});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->source.format, "gltf");
  EXPECT_EQ(scene->source.unit_name, "m");
  ASSERT_EQ(scene->skeleton.num_joints(), 2);
  EXPECT_EQ(scene->skeleton.parent(1), 0);
  EXPECT_TRUE(scene->skeleton.joint(0).rest_translation.isApprox(Eigen::Vector3d(0, 1, 0)));
  // One rotation sampler on the second joint, keys every 0.5 s from 0 to 5.5 s.
  ASSERT_EQ(scene->clips.size(), 1u);
  const MotionClip& clip = scene->clips[0];
  EXPECT_DOUBLE_EQ(clip.sample_rate_hz, 24.0);
  EXPECT_EQ(clip.num_frames, 133);
  EXPECT_NEAR(clip.duration_s(), 5.5, 1e-12);
  EXPECT_EQ(clip.keys[1].rotation_frames.size(), 12u);
  EXPECT_EQ(clip.keys[1].rotation_frames.back(), 132);
  ASSERT_EQ(scene->skins.size(), 1u);
  EXPECT_EQ(scene->skins[0].joints.size(), 2u);
  const MeshPrimitive& prim = scene->meshes.at(0).primitives.at(0);
  EXPECT_EQ(prim.positions.size(), 10u);
  EXPECT_EQ(prim.indices.size(), 24u);
  for (const Eigen::Vector4f& w : prim.weights) EXPECT_NEAR(static_cast<double>(w.sum()), 1.0, 1e-6);
}

TEST(AssimpCorpus, StaticSkinGlbGivesASkeletonAndNoClips) {
  MOCAPFILL_REQUIRE_CORPUS();
  const Result<Scene> scene = ReadWithAssimp(testing::DataPath("assimp/quad_skin.glb"), {});
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  EXPECT_EQ(scene->source.unit_name, "m");
  EXPECT_FALSE(scene->source.unit_detected);
  EXPECT_EQ(scene->skeleton.num_joints(), 21);  // Armature, Bone.000..Bone.009 and their _end nodes
  EXPECT_TRUE(scene->clips.empty());
  ASSERT_EQ(scene->skins.size(), 1u);
  EXPECT_EQ(scene->skins[0].joints.size(), 7u);  // Assimp drops the three bones that weight nothing
  EXPECT_EQ(scene->meshes.at(0).primitives.at(0).positions.size(), 4u);
}

void ExpectInvalidDataNamingFile(const std::string& path) {
  const Result<Scene> scene = ReadWithAssimp(path, {});
  ASSERT_FALSE(scene.ok()) << path;
  EXPECT_EQ(scene.status().code(), ErrorCode::kInvalidData) << scene.status().message();
  EXPECT_NE(scene.status().message().find(path), std::string::npos) << scene.status().message();
}

TEST(AssimpFbxBadInput, GarbageAndTruncatedFilesAreInvalidData) {
  ExpectInvalidDataNamingFile(testing::FixturePath("bad/garbage.fbx"));
  ExpectInvalidDataNamingFile(testing::FixturePath("bad/truncated.fbx"));
}

TEST(AssimpFbxBadInput, EveryTruncationFailsCleanly) {
  std::ifstream in(testing::FixturePath(kFbx), std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_EQ(bytes.size(), 195420u);
  const std::string dir = testing::ScratchDir("assimp_truncations");
  // From inside the header to just before the end of the last top-level record.
  for (size_t length : {0, 10, 27, 100, 5000, 20000, 60000, 120000, 190000, 195000}) {
    const std::string path = dir + "/cut_" + std::to_string(length) + ".fbx";
    std::ofstream(path, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(length));
    ExpectInvalidDataNamingFile(path);
  }
}

TEST(AssimpFbxBadInput, MissingFileIsAnIoError) {
  const std::string path = testing::FixturePath("fbx/does_not_exist.fbx");
  const Result<Scene> scene = ReadWithAssimp(path, {});
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.status().code(), ErrorCode::kIoError);
  EXPECT_NE(scene.status().message().find(path), std::string::npos);
}

}  // namespace
}  // namespace mocapfill
