// Blend weights moved towards the candidates' geometric median posture
// (processing/synthesis/consensus_weights.h): the group positions it measures them by, and
// what it buys the fill on held-out takes.
#include <gtest/gtest.h>

#include <cstdio>

#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "processing/synthesis/consensus_weights.h"
#include "processing/synthesis/hierarchical/hierarchy.h"
#include "tests/processing/held_out_fill.h"
#include "tests/support/default_db.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

// Every upper-body group the fill plans for a legs-keyed sketch on the default database: the
// table holds, for every placed joint, its world position relative to the group's first joint
// taken into that joint's parent frame, as forward kinematics of the frame's pose gives it.
TEST(ConsensusWeights, GroupPositionsAreTheGroupsForwardKinematics) {
  const MotionDatabase& db = testing::DefaultDb();
  const Skeleton& skeleton = db.skeleton();
  std::vector<std::uint8_t> keyed(db.num_joints(), 0);
  for (int j = 0; j < db.num_joints(); ++j) {
    const std::string& name = skeleton.name(j);
    // The skeleton's own root (joint_Root, static above the hips) is held like a key.
    keyed[j] = j == db.root_joint() || skeleton.parent(j) < 0 || name.find("Leg") != std::string::npos ||
               name.find("Foot") != std::string::npos || name.find("Toes") != std::string::npos;
  }
  int groups = 0, placed = 0;
  double worst = 0.0;
  for (const JointGroup& group : PlanGroups(skeleton, keyed)) {
    const Eigen::MatrixXf table = GroupPositions(db, group.joints);
    ASSERT_EQ(table.rows(), db.num_frames());
    std::vector<int> children;
    for (int j = 0; j < db.num_joints(); ++j)
      if (skeleton.parent(j) >= 0 &&
          std::find(group.joints.begin(), group.joints.end(), skeleton.parent(j)) != group.joints.end())
        children.push_back(j);
    ASSERT_EQ(table.cols(), static_cast<int>(3 * children.size())) << group.name;
    ++groups;
    placed += static_cast<int>(children.size());
    const int first = group.joints.front(), parent = skeleton.parent(first);
    for (int f = 0; f < db.num_frames(); f += 97) {
      MotionClip pose = MotionClip::RestPose(skeleton, 1, db.rate_hz());
      for (int j = 0; j < db.num_joints(); ++j)
        pose.rotation(0, j) = db.joint_means()[j] * ExpMap(db.signals().row(f).segment<3>(3 * j).cast<double>().transpose());
      WorldPose world;
      ComputeWorldPose(skeleton, pose, 0, world);
      for (size_t k = 0; k < children.size(); ++k) {
        const Eigen::Quaterniond frame = parent >= 0 ? world.rotations[parent] : Eigen::Quaterniond::Identity();
        const Eigen::Vector3d want = frame.conjugate() * (world.positions[children[k]] - world.positions[first]);
        worst = std::max(worst, (table.row(f).segment<3>(3 * k).cast<double>().transpose() - want).norm());
      }
    }
  }
  std::printf("%d groups, %d placed joints: table within %.2g m of forward kinematics\n", groups, placed, worst);
  EXPECT_EQ(groups, 4);  // torso, neck and head, both arms
  EXPECT_LT(worst, 1e-5);
}

// Root and legs keyed every 8 frames on takes of a style the database lacks: moving each
// upper-body group's blend towards the candidates' median posture lowers the error of the
// synthesised joints on walks and on gestures, and leaves the keys exact.
TEST(ConsensusWeights, LowersTheErrorOfHeldOutTakes) {
  MOCAPFILL_REQUIRE_CORPUS();
  const MotionDatabase& db = testing::BandaiDbWithout("proud");
  FillEngine engine(db);
  std::vector<FillOptions> variants(2);
  variants[0].consensus_iterations = 0;
  Result<testing::ProudSums> sums = testing::FillProudTakesByCategory(engine, db, variants);
  ASSERT_TRUE(sums.ok()) << sums.status().message();
  const std::vector<double>& locomotion = sums->locomotion;
  const std::vector<double>& gestures = sums->gestures;
  EXPECT_LT(sums->key_error_max_deg, 0.01);
  std::printf("unkeyed MPJPE summed, blend as regressed / towards the median: locomotion %.3f / %.3f cm, "
              "gestures %.3f / %.3f cm\n",
              locomotion[0], locomotion[1], gestures[0], gestures[1]);
  EXPECT_LT(locomotion[1], 0.995 * locomotion[0]);  // measured 16.936 against 17.117
  EXPECT_LT(gestures[1], 0.995 * gestures[0]);      // measured 39.089 against 39.513
}

}  // namespace
}  // namespace mocapfill
