// FBX -> glb -> import: the shipped FBX fixtures are converted to glb under
// <build>/test-output/fbx (checked afterwards by the CI glTF-Validator pass) and read back;
// the joint hierarchy, the rest pose, the animation timing and the pose at every frame must
// survive the trip.
#include <gtest/gtest.h>

#include <string>

#include "formats/motion_io.h"
#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

constexpr double kPositionToleranceM = 1e-5;  // float storage of metres-sized values
constexpr double kTimeToleranceS = 1e-6;

std::string ParentName(const Skeleton& s, int j) { return s.parent(j) == kNoParent ? "" : s.name(s.parent(j)); }

class FbxToGlb : public ::testing::TestWithParam<std::string> {};

TEST_P(FbxToGlb, HierarchyTimingAndPoseSurvive) {
  const std::string name = GetParam();
  const Result<Scene> fbx = ImportFile(testing::FixturePath("fbx/" + name + ".fbx"));
  ASSERT_TRUE(fbx.ok()) << fbx.status().message();
  const std::string glb_path = testing::TestOutputDir("fbx") + "/" + name + ".glb";
  const Status written = ExportFile(*fbx, glb_path);
  ASSERT_TRUE(written.ok()) << written.message();
  const Result<Scene> glb = ImportFile(glb_path);
  ASSERT_TRUE(glb.ok()) << glb.status().message();

  const Skeleton &a = fbx->skeleton, &b = glb->skeleton;
  ASSERT_EQ(a.num_joints(), b.num_joints());
  for (int j = 0; j < a.num_joints(); ++j) {
    const std::optional<int> k = b.Find(a.name(j));
    ASSERT_TRUE(k) << "joint " << a.name(j) << " lost";
    EXPECT_EQ(ParentName(b, *k), ParentName(a, j)) << a.name(j);
  }
  ASSERT_EQ(fbx->clips.size(), glb->clips.size());
  EXPECT_EQ(fbx->skins.size(), glb->skins.size());
  for (size_t c = 0; c < fbx->clips.size(); ++c) {
    const MotionClip &ca = fbx->clips[c], &cb = glb->clips[c];
    EXPECT_NEAR(ca.duration_s(), cb.duration_s(), kTimeToleranceS) << ca.name;
    ASSERT_EQ(ca.num_frames, cb.num_frames) << ca.name;
    WorldPose pa, pb;
    for (int f = 0; f < ca.num_frames; ++f) {
      ComputeWorldPose(a, ca, f, pa);
      ComputeWorldPose(b, cb, f, pb);
      for (int j = 0; j < a.num_joints(); ++j) {
        const int k = *b.Find(a.name(j));
        EXPECT_LT((pa.positions[j] - pb.positions[k]).norm(), kPositionToleranceM) << a.name(j) << " frame " << f;
        EXPECT_LT(GeodesicAngle(pa.rotations[j], pb.rotations[k]), 1e-5) << a.name(j) << " frame " << f;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Fixtures, FbxToGlb, ::testing::Values("animation_with_skeleton", "pivot_chain"));

}  // namespace
}  // namespace mocapfill
