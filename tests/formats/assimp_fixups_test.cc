// The Assimp importer's Assimp-free helpers: frame-rate detection from key times, top-4
// influence selection, and baking of uniform joint scales.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "formats/assimp/assimp_fixups.h"
#include "processing/core/rotation.h"

namespace mocapfill::assimp_detail {
namespace {

std::vector<double> Grid(double rate_hz, int frames, double jitter_s = 0.0) {
  std::vector<double> t;
  for (int f = 0; f < frames; ++f) t.push_back(f / rate_hz + ((f % 2) ? jitter_s : -jitter_s));
  return t;
}

TEST(AssimpFixups, DetectsTheLowestRateOnWhichAllKeysLie) {
  EXPECT_EQ(DetectKeyRateHz(Grid(24, 50)).rate_hz, 24.0);
  EXPECT_EQ(DetectKeyRateHz(Grid(25, 50)).rate_hz, 25.0);
  EXPECT_EQ(DetectKeyRateHz(Grid(30, 50)).rate_hz, 30.0);
  EXPECT_EQ(DetectKeyRateHz(Grid(120, 500)).rate_hz, 120.0);
  EXPECT_EQ(DetectKeyRateHz(Grid(60, 7)).rate_hz, 60.0);
  // Every 4th frame of 120 Hz lies on the 30 Hz grid: sparse keys do not force a high rate.
  EXPECT_EQ(DetectKeyRateHz({0.0, 4 / 120.0, 40 / 120.0}).rate_hz, 30.0);
  // Keys from both 24 and 30 Hz grids need 120 Hz.
  EXPECT_EQ(DetectKeyRateHz({0.0, 1 / 24.0, 1 / 30.0}).rate_hz, 120.0);
  // Float noise below the 1e-4 s tolerance is accepted, above it is not.
  EXPECT_EQ(DetectKeyRateHz(Grid(30, 50, 5e-5)).rate_hz, 30.0);
  EXPECT_FALSE(DetectKeyRateHz(Grid(30, 50, 3e-4)).on_grid);
  const DetectedRate none = DetectKeyRateHz({0.0, 0.0123});
  EXPECT_FALSE(none.on_grid);
  EXPECT_EQ(none.rate_hz, 30.0);
  EXPECT_TRUE(DetectKeyRateHz(Grid(24, 50)).on_grid);
}

TEST(AssimpFixups, KeepsTheFourLargestWeightsSummingToOne) {
  const auto top = TopFourInfluences({{3, 0.1f}, {1, 0.3f}, {7, 0.05f}, {2, 0.2f}, {5, 0.25f}, {9, 0.1f}});
  ASSERT_TRUE(top);
  EXPECT_EQ(top->slots, (std::array<std::uint16_t, 4>{1, 5, 2, 3}));  // 0.1 tie: lower slot wins
  EXPECT_EQ(top->weights[0] + top->weights[1] + top->weights[2] + top->weights[3], 1.0f);
  EXPECT_NEAR(top->weights[1] / top->weights[2], 0.25 / 0.2, 1e-6);
}

TEST(AssimpFixups, MergesRepeatedSlotsAndDropsUnusableWeights) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const auto top = TopFourInfluences({{4, 0.2f}, {4, 0.2f}, {6, 0.4f}, {8, 0.0f}, {2, -1.0f}, {3, nan}});
  ASSERT_TRUE(top);
  EXPECT_EQ(top->slots, (std::array<std::uint16_t, 4>{4, 6, 0, 0}));
  EXPECT_FLOAT_EQ(top->weights[0], 0.5f);
  EXPECT_FLOAT_EQ(top->weights[1], 0.5f);
  EXPECT_EQ(top->weights[2], 0.0f);
  EXPECT_EQ(top->weights[3], 0.0f);
  EXPECT_FALSE(TopFourInfluences({{1, 0.0f}, {2, -0.5f}}));
  EXPECT_FALSE(TopFourInfluences({}));
}

// World matrices with full TRS propagation (what glTF and FBX mean by a node tree).
std::vector<Eigen::Matrix4d> TrsWorld(const Skeleton& s) {
  std::vector<Eigen::Matrix4d> world(s.num_joints());
  for (int j = 0; j < s.num_joints(); ++j) {
    const Joint& joint = s.joint(j);
    Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
    local.block<3, 3>(0, 0) = joint.rest_rotation.toRotationMatrix() * joint.rest_scale.asDiagonal();
    local.block<3, 1>(0, 3) = joint.rest_translation;
    world[j] = joint.parent == kNoParent ? local : Eigen::Matrix4d(world[joint.parent] * local);
  }
  return world;
}

TEST(AssimpFixups, BakingUniformScalesKeepsWorldPositionsAndSkinning) {
  std::vector<Joint> joints(3);
  joints[0].name = "armature";
  joints[0].rest_scale = Eigen::Vector3d::Constant(100.0);
  joints[0].rest_rotation = Eigen::Quaterniond(Eigen::AngleAxisd(-0.5 * kPi, Eigen::Vector3d::UnitX()));
  joints[1].name = "bone";
  joints[1].parent = 0;
  joints[1].rest_translation = {0.1, 0.2, 0.0};
  joints[1].rest_scale = Eigen::Vector3d::Constant(2.0);
  joints[2].name = "tip";
  joints[2].parent = 1;
  joints[2].rest_translation = {0.0, 4.5, 0.0};
  Scene scene;
  scene.skeleton = *Skeleton::Build(joints);
  const std::vector<Eigen::Matrix4d> before = TrsWorld(scene.skeleton);
  Skin skin;
  for (int j = 0; j < 3; ++j) {
    skin.joints.push_back(j);
    skin.inverse_bind_matrices.push_back(before[j].inverse());
  }
  scene.skins.push_back(skin);
  MotionClip clip = MotionClip::RestPose(scene.skeleton, 2, 30.0);
  clip.translation(1, 2) = {0.0, 5.0, 0.0};
  scene.clips.push_back(clip);
  Mesh rigid;
  rigid.attach_joint = 2;
  rigid.primitives.resize(1);
  rigid.primitives[0].positions = {Eigen::Vector3f(0.0f, 1.0f, 0.0f)};
  scene.meshes.push_back(rigid);
  const Eigen::Vector3d rigid_world = (before[2] * Eigen::Vector4d(0, 1, 0, 1)).head<3>();

  EXPECT_EQ(BakeUniformJointScales(scene), 2);
  const std::vector<Eigen::Matrix4d> after = TrsWorld(scene.skeleton);
  for (int j = 0; j < 3; ++j) {
    EXPECT_TRUE(scene.skeleton.joint(j).rest_scale.isApprox(Eigen::Vector3d::Ones()));
    const Eigen::Vector3d moved = after[j].block<3, 1>(0, 3), placed = before[j].block<3, 1>(0, 3);
    EXPECT_TRUE(moved.isApprox(placed, 1e-12)) << j;
    EXPECT_TRUE((after[j] * scene.skins[0].inverse_bind_matrices[j]).isIdentity(1e-9)) << j;
  }
  // The tip's offset sits under scales 100 and 2: 4.5 -> 900, the animated 5.0 -> 1000.
  EXPECT_NEAR(scene.skeleton.joint(2).rest_translation.y(), 900.0, 1e-9);
  EXPECT_NEAR(scene.clips[0].translation(1, 2).y(), 1000.0, 1e-9);
  const Eigen::Vector3f p = scene.meshes[0].primitives[0].positions[0];
  EXPECT_TRUE((after[2] * Eigen::Vector4d(p.x(), p.y(), p.z(), 1.0)).head<3>().isApprox(rigid_world, 1e-6));
}

TEST(AssimpFixups, NonUniformScalesStayInRestScale) {
  std::vector<Joint> joints(2);
  joints[0].name = "root";
  joints[0].rest_scale = {1.0, 2.0, 1.0};
  joints[1].name = "child";
  joints[1].parent = 0;
  joints[1].rest_translation = {0.0, 1.0, 0.0};
  Scene scene;
  scene.skeleton = *Skeleton::Build(joints);
  EXPECT_EQ(BakeUniformJointScales(scene), 0);
  EXPECT_EQ(scene.skeleton.joint(0).rest_scale, Eigen::Vector3d(1.0, 2.0, 1.0));
  EXPECT_EQ(scene.skeleton.joint(1).rest_translation, Eigen::Vector3d(0.0, 1.0, 0.0));
}

}  // namespace
}  // namespace mocapfill::assimp_detail
