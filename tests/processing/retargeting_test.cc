// Rig mapping on real skeletons of every naming family, its errors, side checks against the
// pose, and the rest-pose choice (Bandai's zero pose, Geno's bind A-pose and stance T-pose).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "formats/motion_io.h"
#include "formats/name_map_json.h"
#include "processing/retargeting/proportions.h"
#include "processing/retargeting/rest_pose.h"
#include "processing/retargeting/rig_mapping.h"
#include "processing/retargeting/rig_names.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using B = HumanoidBone;
using Expect = std::map<HumanoidBone, std::string>;

Scene Load(const std::string& path) {
  Result<Scene> scene = ImportFile(path);
  EXPECT_TRUE(scene.ok()) << path << ": " << scene.status().message();
  return scene.ok() ? std::move(scene).value() : Scene{};
}

// Maps with the chosen rest's layout, the way `rig show` does.
RigMapping MapScene(const Scene& scene) {
  Result<RigMapping> first = MapHumanoid(scene.skeleton, ZeroPose(scene.skeleton).WorldPositions(scene.skeleton));
  EXPECT_TRUE(first.ok()) << first.status().message();
  if (!first.ok()) return {};
  Result<RigRest> rest = ChooseRest(scene, *first, RestSource::kAuto);
  EXPECT_TRUE(rest.ok()) << rest.status().message();
  if (!rest.ok()) return *first;
  Result<RigMapping> second = MapHumanoid(scene.skeleton, rest->WorldPositions(scene.skeleton));
  EXPECT_TRUE(second.ok()) << second.status().message();
  return second.ok() ? *second : *first;
}

void ExpectBones(const Scene& scene, const RigMapping& m, const Expect& expected) {
  for (int i = 0; i < kNumHumanoidBones; ++i) {
    if (IsRequiredBone(BoneAt(i))) {
      EXPECT_TRUE(m.has(BoneAt(i))) << HumanoidBoneName(BoneAt(i));
    }
  }
  for (const auto& [bone, name] : expected) {
    const int j = m.joint(bone);
    EXPECT_EQ(j >= 0 ? scene.skeleton.name(j) : std::string("(none)"), name) << HumanoidBoneName(bone);
  }
}

const Expect kBandai = {{B::kHips, "Hips"},           {B::kSpine, "Spine"},         {B::kChest, "Chest"},
                        {B::kUpperChest, "(none)"},   {B::kNeck, "Neck"},           {B::kHead, "Head"},
                        {B::kLeftShoulder, "Shoulder_L"}, {B::kLeftUpperArm, "UpperArm_L"}, {B::kLeftLowerArm, "LowerArm_L"},
                        {B::kLeftHand, "Hand_L"},     {B::kRightUpperArm, "UpperArm_R"}, {B::kLeftUpperLeg, "UpperLeg_L"},
                        {B::kLeftLowerLeg, "LowerLeg_L"}, {B::kLeftFoot, "Foot_L"}, {B::kLeftToes, "Toes_L"},
                        {B::kRightToes, "Toes_R"}};
const Expect kCmu = {{B::kHips, "Hips"},          {B::kSpine, "Spine"},          {B::kChest, "Spine1"},
                     {B::kNeck, "Neck"},          {B::kHead, "Head"},            {B::kLeftShoulder, "LeftShoulder"},
                     {B::kLeftUpperArm, "LeftArm"}, {B::kLeftLowerArm, "LeftForeArm"}, {B::kLeftHand, "LeftHand"},
                     {B::kLeftUpperLeg, "LeftUpLeg"}, {B::kLeftLowerLeg, "LeftLeg"}, {B::kLeftFoot, "LeftFoot"},
                     {B::kLeftToes, "LeftToeBase"}, {B::kRightUpperLeg, "RightUpLeg"}};
const Expect kBoxing = {{B::kHips, "Hips"},           {B::kSpine, "Ab"},               {B::kChest, "Chest"},
                        {B::kNeck, "Neck"},           {B::kHead, "Head"},              {B::kLeftShoulder, "LeftCollar"},
                        {B::kLeftUpperArm, "LeftShoulder"}, {B::kLeftLowerArm, "LeftElbow"}, {B::kLeftHand, "LeftWrist"},
                        {B::kRightUpperArm, "RightShoulder"}, {B::kLeftUpperLeg, "LeftHip"}, {B::kLeftLowerLeg, "LeftKnee"},
                        {B::kLeftFoot, "LeftAnkle"},  {B::kLeftToes, "LeftToes"}};
const Expect kGeno = {{B::kHips, "Hips"},          {B::kSpine, "Spine"},          {B::kChest, "Spine2"},
                      {B::kUpperChest, "Spine3"},  {B::kNeck, "Neck"},            {B::kHead, "Head"},
                      {B::kLeftShoulder, "LeftShoulder"}, {B::kLeftUpperArm, "LeftArm"}, {B::kLeftLowerArm, "LeftForeArm"},
                      {B::kLeftHand, "LeftHand"},  {B::kLeftUpperLeg, "LeftUpLeg"}, {B::kLeftLowerLeg, "LeftLeg"},
                      {B::kLeftFoot, "LeftFoot"},  {B::kLeftToes, "LeftToeBase"}, {B::kRightToes, "RightToeBase"}};

TEST(RigMappingFixtures, BandaiCmuBoxing) {
  {
    const Scene s = Load(testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"));
    const RigMapping m = MapScene(s);
    EXPECT_EQ(m.family, "bandai-namco");
    ExpectBones(s, m, kBandai);
  }
  {
    const Scene s = Load(testing::FixturePath("bvh/cmu_01_01_short.bvh"));
    const RigMapping m = MapScene(s);
    EXPECT_EQ(m.family, "cmu");
    ExpectBones(s, m, kCmu);
  }
  {
    const Scene s = Load(testing::FixturePath("bvh/boxing_toes_short.bvh"));
    const RigMapping m = MapScene(s);
    EXPECT_EQ(m.family, "biovision");
    ExpectBones(s, m, kBoxing);  // LeftShoulder is the upper arm here: its parent is the collar
  }
}

TEST(RigMappingFixtures, MixamoRigifySmpl) {
  {
    const Scene s = Load(testing::FixturePath("rigs/mixamo_prefixed.bvh"));
    const RigMapping m = MapScene(s);
    EXPECT_EQ(m.family, "mixamo");
    ExpectBones(s, m, {{B::kHips, "mixamorig:Hips"}, {B::kSpine, "mixamorig:Spine"}, {B::kChest, "mixamorig:Spine1"},
                       {B::kUpperChest, "mixamorig:Spine2"}, {B::kNeck, "mixamorig:Neck"}, {B::kHead, "mixamorig:Head"},
                       {B::kLeftShoulder, "mixamorig:LeftShoulder"}, {B::kLeftUpperArm, "mixamorig:LeftArm"},
                       {B::kRightHand, "mixamorig:RightHand"}, {B::kLeftToes, "mixamorig:LeftToeBase"}});
  }
  {
    const Scene s = Load(testing::FixturePath("rigs/rigify_def.bvh"));
    const RigMapping m = MapScene(s);
    EXPECT_EQ(m.family, "rigify");
    ExpectBones(s, m, {{B::kHips, "DEF-spine"}, {B::kSpine, "DEF-spine.001"}, {B::kChest, "DEF-spine.002"},
                       {B::kUpperChest, "DEF-spine.003"}, {B::kNeck, "DEF-spine.004"}, {B::kHead, "DEF-spine.006"},
                       {B::kLeftShoulder, "DEF-shoulder.L"}, {B::kLeftUpperArm, "DEF-upper_arm.L"},
                       {B::kLeftLowerArm, "DEF-forearm.L"}, {B::kLeftHand, "DEF-hand.L"}, {B::kLeftUpperLeg, "DEF-thigh.L"},
                       {B::kLeftLowerLeg, "DEF-shin.L"}, {B::kLeftFoot, "DEF-foot.L"}, {B::kLeftToes, "DEF-toe.L"}});
    EXPECT_EQ(UnmappedJointReason(s.skeleton, m, *s.skeleton.Find("DEF-forearm.L.001")), "twist helper");
  }
  {
    const Scene s = Load(testing::FixturePath("rigs/smpl_body.bvh"));
    const RigMapping m = MapScene(s);
    EXPECT_EQ(m.family, "smpl");
    ExpectBones(s, m, {{B::kHips, "Pelvis"}, {B::kSpine, "Spine1"}, {B::kChest, "Spine2"}, {B::kUpperChest, "Spine3"},
                       {B::kNeck, "Neck"}, {B::kHead, "Head"}, {B::kLeftShoulder, "L_Collar"},
                       {B::kLeftUpperArm, "L_Shoulder"}, {B::kLeftLowerArm, "L_Elbow"}, {B::kLeftHand, "L_Wrist"},
                       {B::kLeftUpperLeg, "L_Hip"}, {B::kLeftLowerLeg, "L_Knee"}, {B::kLeftFoot, "L_Ankle"},
                       {B::kLeftToes, "L_Foot"}, {B::kRightUpperArm, "R_Shoulder"}, {B::kRightHand, "R_Wrist"}});
    EXPECT_EQ(s.skeleton.num_joints(), 24);  // SMPL's 24, L_Hand and R_Hand included
    EXPECT_EQ(UnmappedJointReason(s.skeleton, m, *s.skeleton.Find("L_Hand")), "below the hand (fingers, hand end)");
  }
}

// The Unreal naming on a real character (Quaternius, CC0; fixtures/README.md).
TEST(RigMappingFixtures, UnrealNamedCharacter) {
  const Scene s = Load(testing::FixturePath("rigs/unreal_quaternius.bvh"));
  const RigMapping m = MapScene(s);
  EXPECT_EQ(m.family, "unreal");
  ExpectBones(s, m, {{B::kHips, "pelvis"}, {B::kSpine, "spine_01"}, {B::kChest, "spine_02"}, {B::kUpperChest, "spine_03"},
                     {B::kNeck, "neck_01"}, {B::kHead, "Head"}, {B::kLeftShoulder, "clavicle_l"},
                     {B::kLeftUpperArm, "upperarm_l"}, {B::kLeftLowerArm, "lowerarm_l"}, {B::kLeftHand, "hand_l"},
                     {B::kRightHand, "hand_r"}, {B::kLeftUpperLeg, "thigh_l"}, {B::kLeftLowerLeg, "calf_l"},
                     {B::kLeftFoot, "foot_l"}, {B::kLeftToes, "ball_l"}, {B::kRightToes, "ball_r"}});
  EXPECT_TRUE(m.warnings.empty());
  EXPECT_EQ(UnmappedJointReason(s.skeleton, m, *s.skeleton.Find("root")), "root above the hips");
}

TEST(RigMappingCorpus, RealRigs) {
  MOCAPFILL_REQUIRE_CORPUS();
  const std::vector<std::string> bandai = testing::CorpusFiles("bandai-namco-1/data", ".bvh");
  ASSERT_FALSE(bandai.empty());
  {
    const Scene s = Load(bandai.front());
    ExpectBones(s, MapScene(s), kBandai);
  }
  {
    const Scene s = Load(testing::DataPath("cmu/01_01.bvh"));
    ExpectBones(s, MapScene(s), kCmu);
  }
  {
    const Scene s = Load(testing::DataPath("assimp/Boxing_Toes.bvh"));
    ExpectBones(s, MapScene(s), kBoxing);
  }
  for (const char* f : {"geno/Geno.fbx", "geno/Geno_bind.bvh", "geno/Geno_stance.bvh"}) {
    SCOPED_TRACE(f);
    const Scene s = Load(testing::DataPath(f));
    const RigMapping m = MapScene(s);
    EXPECT_EQ(m.family, "geno");
    ExpectBones(s, m, kGeno);
    EXPECT_TRUE(m.warnings.empty());
  }
}

void ExpectNotHumanoid(const std::string& path) {
  SCOPED_TRACE(path);
  const Scene s = Load(path);
  Result<RigMapping> m = MapHumanoid(s.skeleton, {});
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.status().code(), ErrorCode::kInvalidData);
  EXPECT_NE(m.status().message().find("not a humanoid rig"), std::string::npos) << m.status().message();
  EXPECT_NE(m.status().message().find("leftUpperLeg"), std::string::npos) << m.status().message();
}

TEST(RigMappingErrors, NonHumanoidRigs) {
  ExpectNotHumanoid(testing::FixturePath("fbx/animation_with_skeleton.fbx"));
  ExpectNotHumanoid(testing::FixturePath("gltf/simple_skin.gltf"));
}

TEST(RigMappingErrors, NonHumanoidCorpus) {
  MOCAPFILL_REQUIRE_CORPUS();
  ExpectNotHumanoid(testing::DataPath("assimp/animation_with_skeleton.fbx"));
  ExpectNotHumanoid(testing::DataPath("assimp/simple_skin.gltf"));
}

TEST(RigMappingErrors, BadMaps) {
  const Scene s = Load(testing::FixturePath("bvh/cmu_01_01_short.bvh"));
  RigMapOptions options;
  options.overrides = {{"LeftUpLge", "leftUpperLeg"}};
  Result<RigMapping> m = MapHumanoid(s.skeleton, {}, options);
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.status().message().find("'LeftUpLeg'"), std::string::npos) << m.status().message();

  options.overrides = {{"LeftUpLeg", "leftThigh"}};
  m = MapHumanoid(s.skeleton, {}, options);
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.status().message().find("leftUpperLeg"), std::string::npos) << m.status().message();
  EXPECT_NE(m.status().message().find("valid"), std::string::npos) << m.status().message();

  options.overrides = {{"LHipJoint", "leftUpperLeg"}, {"LeftUpLeg", "leftUpperLeg"}};
  m = MapHumanoid(s.skeleton, {}, options);
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.status().message().find("'LHipJoint'"), std::string::npos) << m.status().message();
  EXPECT_NE(m.status().message().find("'LeftUpLeg'"), std::string::npos) << m.status().message();

  options.overrides = {{"LeftToeBase", ""}};  // unmapping an optional bone is fine
  m = MapHumanoid(s.skeleton, {}, options);
  ASSERT_TRUE(m.ok()) << m.status().message();
  EXPECT_FALSE(m->has(B::kLeftToes));

  EXPECT_FALSE(ParseNameMapJson("[1, 2]", "--map", kRigMapShape).ok());
  EXPECT_FALSE(ParseNameMapJson("{\"a\": 3}", "--map", kRigMapShape).ok());
  Result<std::map<std::string, std::string>> parsed =
      ParseNameMapJson("{\"a\": \"hips\", \"b\": null}", "map.json", kRigMapShape);
  ASSERT_TRUE(parsed.ok());
  EXPECT_EQ(parsed->at("a"), "hips");
  EXPECT_EQ(parsed->at("b"), "");
}

Joint MakeJoint(const std::string& name, int parent, Eigen::Vector3d offset) {
  Joint j;
  j.name = name;
  j.parent = parent;
  j.rest_translation = offset;
  return j;
}

// A small stick figure (metres): hips, spine, chest, neck, head, arms with clavicles, legs.
std::vector<Joint> StickFigure(bool with_legs) {
  std::vector<Joint> j;
  j.push_back(MakeJoint("Hips", -1, {0, 1.0, 0}));
  j.push_back(MakeJoint("Spine", 0, {0, 0.15, 0}));
  j.push_back(MakeJoint("Chest", 1, {0, 0.2, 0}));
  j.push_back(MakeJoint("Neck", 2, {0, 0.2, 0}));
  j.push_back(MakeJoint("Head", 3, {0, 0.1, 0}));
  for (int side = 0; side < 2; ++side) {
    const double x = side == 0 ? 1 : -1;
    const std::string s = side == 0 ? "Left" : "Right";
    const int base = static_cast<int>(j.size());
    j.push_back(MakeJoint(s + "Shoulder", 2, {x * 0.05, 0.15, 0}));
    j.push_back(MakeJoint(s + "Arm", base, {x * 0.1, 0, 0}));
    j.push_back(MakeJoint(s + "ForeArm", base + 1, {x * 0.25, 0, 0}));
    j.push_back(MakeJoint(s + "Hand", base + 2, {x * 0.25, 0, 0}));
  }
  if (with_legs) {
    for (int side = 0; side < 2; ++side) {
      const double x = side == 0 ? 1 : -1;
      const std::string s = side == 0 ? "Left" : "Right";
      const int base = static_cast<int>(j.size());
      j.push_back(MakeJoint(s + "UpLeg", 0, {x * 0.1, -0.05, 0}));
      j.push_back(MakeJoint(s + "Leg", base, {0, -0.45, 0}));
      j.push_back(MakeJoint(s + "Foot", base + 1, {0, -0.45, 0}));
      j.push_back(MakeJoint(s + "ToeBase", base + 2, {0, -0.05, 0.12}));
    }
  }
  return j;
}

TEST(RigMappingErrors, NoLegsNamesLeftUpperLeg) {
  Result<Skeleton> skeleton = Skeleton::Build(StickFigure(false));
  ASSERT_TRUE(skeleton.ok());
  Result<RigMapping> m = MapHumanoid(*skeleton, ZeroPose(*skeleton).WorldPositions(*skeleton));
  ASSERT_FALSE(m.ok());
  EXPECT_EQ(m.status().code(), ErrorCode::kInvalidData);
  EXPECT_NE(m.status().message().find("no leftUpperLeg"), std::string::npos) << m.status().message();
}

TEST(RigMappingErrors, TwoHipsCandidates) {
  // The right leg hangs from a second root named Pelvis: the legs do not meet.
  std::vector<Joint> joints = StickFigure(true);
  // Keep everything but the right leg (the last four joints), then add the second root.
  std::vector<Joint> reordered(joints.begin(), joints.end() - 4);
  reordered.push_back(MakeJoint("Pelvis", -1, {0, 1.0, 0}));
  const int p = static_cast<int>(reordered.size()) - 1;
  reordered.push_back(MakeJoint("RightUpLeg", p, {-0.1, -0.05, 0}));
  reordered.push_back(MakeJoint("RightLeg", p + 1, {0, -0.45, 0}));
  reordered.push_back(MakeJoint("RightFoot", p + 2, {0, -0.45, 0}));
  Result<Skeleton> skeleton = Skeleton::Build(reordered);
  ASSERT_TRUE(skeleton.ok()) << skeleton.status().message();
  Result<RigMapping> m = MapHumanoid(*skeleton, {});
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.status().message().find("two candidates for the hips"), std::string::npos) << m.status().message();
  EXPECT_NE(m.status().message().find("'Hips'"), std::string::npos);
  EXPECT_NE(m.status().message().find("'Pelvis'"), std::string::npos);
}

// The Unreal Mannequin's names and hierarchy (no pose: no published rest offsets were found,
// see fixtures/README.md), with its root, twist and IK helpers.
TEST(RigMappingNames, UnrealMannequinByNamesAndHierarchy) {
  std::vector<Joint> j;
  auto add = [&](const std::string& name, const std::string& parent) {
    int p = -1;
    for (size_t k = 0; k < j.size(); ++k)
      if (j[k].name == parent) p = static_cast<int>(k);
    j.push_back(MakeJoint(name, p, Eigen::Vector3d::Zero()));
  };
  add("root", "");
  add("pelvis", "root");
  add("spine_01", "pelvis");
  add("spine_02", "spine_01");
  add("spine_03", "spine_02");
  add("neck_01", "spine_03");
  add("head", "neck_01");
  for (const std::string s : {"l", "r"}) {
    add("clavicle_" + s, "spine_03");
    add("upperarm_" + s, "clavicle_" + s);
    add("upperarm_twist_01_" + s, "upperarm_" + s);
    add("lowerarm_" + s, "upperarm_" + s);
    add("lowerarm_twist_01_" + s, "lowerarm_" + s);
    add("hand_" + s, "lowerarm_" + s);
    add("thigh_" + s, "pelvis");
    add("thigh_twist_01_" + s, "thigh_" + s);
    add("calf_" + s, "thigh_" + s);
    add("calf_twist_01_" + s, "calf_" + s);
    add("foot_" + s, "calf_" + s);
    add("ball_" + s, "foot_" + s);
  }
  add("ik_foot_root", "root");
  add("ik_foot_l", "ik_foot_root");
  Result<Skeleton> skeleton = Skeleton::Build(j);
  ASSERT_TRUE(skeleton.ok());
  Result<RigMapping> m = MapHumanoid(*skeleton, {});
  ASSERT_TRUE(m.ok()) << m.status().message();
  EXPECT_EQ(m->family, "unreal");
  const Scene scene{*skeleton, {}, {}, {}, {}, {}};
  ExpectBones(scene, *m, {{B::kHips, "pelvis"}, {B::kSpine, "spine_01"}, {B::kChest, "spine_02"},
                          {B::kUpperChest, "spine_03"}, {B::kNeck, "neck_01"}, {B::kHead, "head"},
                          {B::kLeftShoulder, "clavicle_l"}, {B::kLeftUpperArm, "upperarm_l"},
                          {B::kLeftLowerArm, "lowerarm_l"}, {B::kLeftHand, "hand_l"}, {B::kRightHand, "hand_r"},
                          {B::kLeftUpperLeg, "thigh_l"}, {B::kLeftLowerLeg, "calf_l"}, {B::kLeftFoot, "foot_l"},
                          {B::kLeftToes, "ball_l"}});
  EXPECT_EQ(UnmappedJointReason(*skeleton, *m, 0), "root above the hips");
  EXPECT_EQ(UnmappedJointReason(*skeleton, *m, *skeleton->Find("ik_foot_l")), "IK helper");
  EXPECT_EQ(UnmappedJointReason(*skeleton, *m, *skeleton->Find("thigh_twist_01_l")), "twist helper");
}

TEST(RigMappingSides, MirroredRigGeometryWins) {
  Scene s = Load(testing::FixturePath("bvh/cmu_01_01_short.bvh"));
  std::vector<Joint> joints = s.skeleton.joints();
  for (Joint& j : joints) j.rest_translation.x() = -j.rest_translation.x();
  Result<Skeleton> mirrored = Skeleton::Build(joints);
  ASSERT_TRUE(mirrored.ok());
  Result<RigMapping> m = MapHumanoid(*mirrored, ZeroPose(*mirrored).WorldPositions(*mirrored));
  ASSERT_TRUE(m.ok()) << m.status().message();
  ASSERT_FALSE(m->warnings.empty());
  EXPECT_NE(m->warnings.front().find("geometry wins"), std::string::npos);
  EXPECT_EQ(mirrored->name(m->joint(B::kLeftUpperLeg)), "RightUpLeg");
  EXPECT_EQ(mirrored->name(m->joint(B::kLeftHand)), "RightHand");
  // Unmirrored: no warning, names agree with geometry.
  Result<RigMapping> plain = MapHumanoid(s.skeleton, ZeroPose(s.skeleton).WorldPositions(s.skeleton));
  ASSERT_TRUE(plain.ok());
  EXPECT_TRUE(plain->warnings.empty());
}

// The skeleton with every joint renamed by `rename(index, name)`.
template <typename Rename>
Skeleton Renamed(const Skeleton& skeleton, Rename rename) {
  std::vector<Joint> joints = skeleton.joints();
  for (size_t i = 0; i < joints.size(); ++i) joints[i].name = rename(static_cast<int>(i), joints[i].name);
  Result<Skeleton> out = Skeleton::Build(joints);
  EXPECT_TRUE(out.ok()) << out.status().message();
  return out.ok() ? std::move(out).value() : Skeleton{};
}

// Maps `renamed` (the same joints as `scene`'s, other names) with the named rig's chosen rest
// and checks that `bones` land on the same joints as with the names.
void ExpectSameJoints(const Scene& scene, const Skeleton& renamed, const std::vector<HumanoidBone>& bones) {
  const RigMapping named = MapScene(scene);
  Result<RigRest> rest = ChooseRest(scene, named, RestSource::kAuto);
  ASSERT_TRUE(rest.ok()) << rest.status().message();
  Result<RigMapping> m = MapHumanoid(renamed, rest->WorldPositions(scene.skeleton));
  ASSERT_TRUE(m.ok()) << m.status().message();
  for (HumanoidBone bone : bones) {
    const int j = m->joint(bone), want = named.joint(bone);
    EXPECT_EQ(j, want) << HumanoidBoneName(bone) << ": " << (j >= 0 ? scene.skeleton.name(j) : "(none)")
                       << " instead of " << (want >= 0 ? scene.skeleton.name(want) : "(none)");
  }
  EXPECT_TRUE(m->warnings.empty()) << m->warnings.front();
}

// Every bone: sides and limbs come from the pose when the names carry no side word.
std::vector<HumanoidBone> AllBones() {
  std::vector<HumanoidBone> out;
  for (int i = 0; i < kNumHumanoidBones; ++i) out.push_back(BoneAt(i));
  return out;
}

// With no names at all, the limbs and the hips (the torso split and the head need words such
// as "end" and "eye" to tell an end bone or an eye from the head).
const std::vector<HumanoidBone> kLimbs = {
    B::kHips,          B::kLeftUpperLeg,  B::kLeftLowerLeg,  B::kLeftFoot,      B::kRightUpperLeg,
    B::kRightLowerLeg, B::kRightFoot,     B::kLeftUpperArm,  B::kLeftLowerArm,  B::kLeftHand,
    B::kRightUpperArm, B::kRightLowerArm, B::kRightHand,     B::kLeftShoulder,  B::kRightShoulder};

void ExpectPoseFindsLimbs(const std::string& path) {
  SCOPED_TRACE(path);
  const Scene s = Load(path);
  // "LeftUpLeg" -> "UpLeg_12", "mixamorig:LeftHand" -> "Hand_30": the words without a side.
  const Skeleton sideless = Renamed(s.skeleton, [](int i, const std::string& name) {
    return rig_names::ParseJointName(name).stem + "_" + std::to_string(i);
  });
  ExpectSameJoints(s, sideless, AllBones());
  const Skeleton anonymous = Renamed(s.skeleton, [](int i, const std::string&) { return "joint_" + std::to_string(i); });
  ExpectSameJoints(s, anonymous, kLimbs);
}

TEST(RigMappingByPose, NamesWithoutSidesFixtures) {
  for (const char* f : {"bvh/bandai_walk_normal_001_short.bvh", "bvh/cmu_01_01_short.bvh", "bvh/boxing_toes_short.bvh",
                        "rigs/mixamo_prefixed.bvh", "rigs/smpl_body.bvh", "rigs/unreal_quaternius.bvh"})
    ExpectPoseFindsLimbs(testing::FixturePath(f));
}

TEST(RigMappingByPose, NamesWithoutSidesCorpus) {
  MOCAPFILL_REQUIRE_CORPUS();
  for (const char* f : {"geno/Geno.fbx", "geno/Geno_bind.bvh", "geno/Geno_stance.bvh", "cmu/01_01.bvh"})
    ExpectPoseFindsLimbs(testing::DataPath(f));
}

// A rig the pose shows nothing humanoid in keeps the plain refusal, with the pose's reason.
TEST(RigMappingByPose, NonHumanoidPoseSaysWhy) {
  const Scene s = Load(testing::FixturePath("fbx/animation_with_skeleton.fbx"));
  Result<RigMapping> m = MapHumanoid(s.skeleton, ZeroPose(s.skeleton).WorldPositions(s.skeleton));
  ASSERT_FALSE(m.ok());
  EXPECT_NE(m.status().message().find("not a humanoid rig"), std::string::npos) << m.status().message();
  EXPECT_NE(m.status().message().find("rest pose"), std::string::npos) << m.status().message();
}

// Angle of the upper arm below horizontal, degrees.
double UpperArmDrop(const Scene& s, const RigMapping& m, const RigRest& rest) {
  const std::vector<Eigen::Vector3d> p = rest.WorldPositions(s.skeleton);
  const Eigen::Vector3d d = (p[m.joint(B::kLeftLowerArm)] - p[m.joint(B::kLeftUpperArm)]).normalized();
  return std::asin(-d.y()) * 180.0 / 3.14159265358979;
}

TEST(RestPose, BandaiZeroPoseIsNoStandingPose) {
  const Scene s = Load(testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"));
  Result<RigMapping> m = MapHumanoid(s.skeleton, ZeroPose(s.skeleton).WorldPositions(s.skeleton));
  ASSERT_TRUE(m.ok()) << m.status().message();
  EXPECT_FALSE(IsStandingPose(s.skeleton, *m, ZeroPose(s.skeleton)));
  Result<RigRest> rest = ChooseRest(s, *m, RestSource::kAuto);
  ASSERT_TRUE(rest.ok()) << rest.status().message();
  EXPECT_EQ(rest->source, RestSource::kMean);
  EXPECT_NE(rest->reason.find("zero pose is no standing pose"), std::string::npos) << rest->reason;
  EXPECT_NE(rest->reason.find("the mean pose of clip"), std::string::npos) << rest->reason;
  EXPECT_TRUE(IsStandingPose(s.skeleton, *m, *rest));
  Result<RigRest> first = ChooseRest(s, *m, RestSource::kFirstFrame);
  ASSERT_TRUE(first.ok());
  EXPECT_EQ(first->source, RestSource::kFirstFrame);
  const RigProportions prop = MeasureProportions(s.skeleton, *m, *rest);
  EXPECT_GT(prop.hip_height, 0.8);
  EXPECT_LT(prop.hip_height, 1.1);
}

TEST(RestPose, CmuZeroPoseStands) {
  const Scene s = Load(testing::FixturePath("bvh/cmu_01_01_short.bvh"));
  Result<RigMapping> m = MapHumanoid(s.skeleton, ZeroPose(s.skeleton).WorldPositions(s.skeleton));
  ASSERT_TRUE(m.ok());
  Result<RigRest> rest = ChooseRest(s, *m, RestSource::kAuto);
  ASSERT_TRUE(rest.ok());
  EXPECT_EQ(rest->source, RestSource::kZero);
  EXPECT_NEAR(UpperArmDrop(s, *m, *rest), 0.0, 10.0);  // CMU's zero pose is a T-pose
}

TEST(RestPose, Geno) {
  MOCAPFILL_REQUIRE_CORPUS();
  {
    const Scene s = Load(testing::DataPath("geno/Geno.fbx"));
    const RigMapping m = MapScene(s);
    EXPECT_TRUE(IsStandingPose(s.skeleton, m, ZeroPose(s.skeleton)));
    Result<RigRest> rest = ChooseRest(s, m, RestSource::kAuto);
    ASSERT_TRUE(rest.ok()) << rest.status().message();
    EXPECT_EQ(rest->source, RestSource::kBind);
    EXPECT_TRUE(IsStandingPose(s.skeleton, m, *rest));
    const double drop = UpperArmDrop(s, m, *rest);
    RecordProperty("geno_bind_upper_arm_drop_deg", std::to_string(drop));
    EXPECT_NEAR(drop, 45.0, 10.0);  // the A-pose
    EXPECT_NEAR(UpperArmDrop(s, m, ZeroPose(s.skeleton)), 0.0, 10.0);  // the nodes' T-pose
  }
  for (const char* f : {"geno/Geno_bind.bvh", "geno/Geno_stance.bvh"}) {
    SCOPED_TRACE(f);
    const Scene s = Load(testing::DataPath(f));
    const RigMapping m = MapScene(s);
    EXPECT_TRUE(IsStandingPose(s.skeleton, m, ZeroPose(s.skeleton)));
    Result<RigRest> first = ChooseRest(s, m, RestSource::kFirstFrame);
    ASSERT_TRUE(first.ok());
    EXPECT_TRUE(IsStandingPose(s.skeleton, m, *first));
    const double drop = UpperArmDrop(s, m, *first);
    const double expected = std::string(f) == "geno/Geno_stance.bvh" ? 0.0 : 45.0;
    EXPECT_NEAR(drop, expected, 10.0);
  }
}

}  // namespace
}  // namespace mocapfill
