#include "processing/database/motion_database_builder.h"

#include <gtest/gtest.h>

#include "processing/database/stored_clips.h"
#include "tests/processing/synthetic_motion.h"

namespace mocapfill {
namespace {

using testing::WalkerClip;
using testing::WalkerParams;
using testing::WalkerSkeleton;

// Float32 storage of tangent coordinates and re-integrated root features.
constexpr double kStorageRad = 1e-5;
constexpr double kStorageM = 1e-4;

MotionDatabaseBuilder WalkerBuilder(DatabaseOptions options = {}) {
  MotionDatabaseBuilder builder(options);
  const Skeleton skeleton = WalkerSkeleton();
  for (int i = 0; i < 3; ++i) {
    WalkerParams p;
    p.duration_s = 3.0 + i;
    p.phase_rad = 0.7 * i;
    p.rate_hz = i == 2 ? 120.0 : 30.0;  // one clip needs resampling
    MotionClip clip = WalkerClip(skeleton, p);
    clip.name = "walk_" + std::to_string(i);
    EXPECT_TRUE(builder.Add(skeleton, clip, {{"content", "walk"}, {"id", std::to_string(i)}}).ok());
  }
  return builder;
}

TEST(MotionDatabase, OptionsValidateRejectsEveryInvalidValue) {
  DatabaseOptions options;
  EXPECT_TRUE(options.Validate().ok());
  options.rate_hz = -1.0;
  EXPECT_EQ(options.Validate().code(), ErrorCode::kInvalidArgument);
  options = {};
  options.stored_band_hz = {20.0};
  EXPECT_FALSE(options.Validate().ok());
  options = {};
  options.correlation_max_lag_s = -0.1;
  EXPECT_FALSE(options.Validate().ok());
  options = {};
  options.threads = -2;
  EXPECT_FALSE(options.Validate().ok());
  EXPECT_EQ(MotionDatabaseBuilder().Build().status().code(), ErrorCode::kInvalidArgument);
}

TEST(MotionDatabase, BuildsSignalsBandsAndCorrelation) {
  Result<MotionDatabase> db = WalkerBuilder().Build();
  ASSERT_TRUE(db.ok()) << db.status().message();
  EXPECT_EQ(db->num_clips(), 3);
  EXPECT_EQ(db->root_joint(), 1);
  EXPECT_EQ(db->num_channels(), 3 * 6 + kNumRootFeatures);
  EXPECT_EQ(db->num_frames(), 91 + 121 + 151);
  EXPECT_EQ(db->clip(2).first_frame, 91 + 121);
  EXPECT_EQ(db->clip(1).labels.at("id"), "1");
  EXPECT_EQ(db->ChannelName(TangentColumn(4, 0)), "Leg_L.x");
  EXPECT_EQ(db->ChannelName(db->RootFeatureChannel(kRootYawRate)), "root.yaw_rate_radps");
  ASSERT_EQ(db->bands().size(), 3u);
  EXPECT_EQ(db->bands()[0].band, 2);
  ASSERT_NE(db->FindBand(3), nullptr);
  EXPECT_EQ(db->FindBand(0), nullptr);
  // The legs swing in exact anti-phase: correlation -1 at lag 0 in the stride band.
  const CorrelationTable& table = db->correlation();
  EXPECT_EQ(table.band, 3);
  EXPECT_EQ(table.max_lag_frames, 8);  // round(0.25 s * 30 Hz)
  const CorrelationEntry legs = table.at(TangentColumn(4, 0), TangentColumn(5, 0));
  EXPECT_LT(legs.value, -0.99f);
  EXPECT_EQ(legs.lag_frames, 0);
  // A leg and the 0.4 Hz head nod share little of the stride band.
  EXPECT_LT(table.at(TangentColumn(4, 0), TangentColumn(3, 0)).max_abs, 0.5f);
  EXPECT_GT(db->MemoryBytes(), sizeof(float) * db->num_frames() * db->num_channels() * 4);
}

TEST(MotionDatabase, ReconstructedClipsMatchTheInputs) {
  Result<MotionDatabase> db = WalkerBuilder().Build();
  ASSERT_TRUE(db.ok());
  const Skeleton skeleton = WalkerSkeleton();
  WalkerParams p;
  p.duration_s = 4.0;
  p.phase_rad = 0.7;
  const MotionClip original = WalkerClip(skeleton, p);
  Result<MotionClip> clip = ReconstructClip(*db, 1);
  ASSERT_TRUE(clip.ok()) << clip.status().message();
  EXPECT_EQ(clip->name, "walk_1");
  ASSERT_EQ(clip->num_frames, original.num_frames);
  EXPECT_LT(testing::MaxRotationError(*clip, original), kStorageRad);
  EXPECT_LT(testing::MaxTranslationError(*clip, original), kStorageM);
  EXPECT_FALSE(ReconstructClip(*db, 3).ok());
}

TEST(MotionDatabase, BuildIsDeterministicWhateverTheThreadCount) {
  DatabaseOptions one;
  one.threads = 1;
  DatabaseOptions two;
  two.threads = 2;
  Result<MotionDatabase> a = WalkerBuilder(one).Build();
  Result<MotionDatabase> b = WalkerBuilder(two).Build();
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_TRUE(a->signals() == b->signals());
  for (size_t i = 0; i < a->bands().size(); ++i) EXPECT_TRUE(a->bands()[i].values == b->bands()[i].values);
  for (size_t i = 0; i < a->correlation().entries.size(); ++i) {
    EXPECT_EQ(a->correlation().entries[i].value, b->correlation().entries[i].value);
    EXPECT_EQ(a->correlation().entries[i].lag_frames, b->correlation().entries[i].lag_frames);
  }
}

Skeleton RenamedWalker(const std::string& from, const std::string& to) {
  std::vector<Joint> joints = WalkerSkeleton().joints();
  for (Joint& j : joints)
    if (j.name == from) j.name = to;
  return Skeleton::Build(joints).value();
}

TEST(MotionDatabase, RejectsADifferentSkeletonNamingTheJoint) {
  MotionDatabaseBuilder builder;
  const Skeleton skeleton = WalkerSkeleton();
  ASSERT_TRUE(builder.Add(skeleton, WalkerClip(skeleton, {}), {}).ok());
  const Skeleton renamed = RenamedWalker("Leg_L", "LeftLeg");
  Status status = builder.Add(renamed, WalkerClip(renamed, {}), {});
  EXPECT_EQ(status.code(), ErrorCode::kInvalidData);
  EXPECT_NE(status.message().find("'Leg_L'"), std::string::npos) << status.message();
  // Leg_R re-attached under Spine.
  std::vector<Joint> joints = skeleton.joints();
  joints[5].parent = 2;
  const Skeleton reparented = Skeleton::Build(joints).value();
  status = builder.Add(reparented, WalkerClip(reparented, {}), {});
  EXPECT_NE(status.message().find("joint 'Leg_R' has parent 'Spine'"), std::string::npos) << status.message();
  EXPECT_EQ(builder.num_clips(), 1);
}

TEST(MotionDatabase, JointNameMapAndJointOrderAreHandled) {
  MotionDatabaseBuilder builder;
  builder.SetJointNameMap({{"LeftLeg", "Leg_L"}});
  const Skeleton skeleton = WalkerSkeleton();
  ASSERT_TRUE(builder.Add(skeleton, WalkerClip(skeleton, {}), {}).ok());
  const Skeleton renamed = RenamedWalker("Leg_L", "LeftLeg");
  EXPECT_TRUE(builder.Add(renamed, WalkerClip(renamed, {}), {}).ok());
  // Same joints, legs listed in the other order.
  std::vector<Joint> joints = skeleton.joints();
  std::swap(joints[4], joints[5]);
  const Skeleton swapped = Skeleton::Build(joints).value();
  MotionClip clip = WalkerClip(skeleton, {});
  for (int f = 0; f < clip.num_frames; ++f) std::swap(clip.rotation(f, 4), clip.rotation(f, 5));
  ASSERT_TRUE(builder.Add(swapped, clip, {}).ok());
  Result<MotionDatabase> db = builder.Build();
  ASSERT_TRUE(db.ok());
  // The re-ordered clip equals the first one in database order.
  EXPECT_TRUE(db->ClipRows(db->signals(), 2) == db->ClipRows(db->signals(), 0));
}

TEST(MotionDatabase, FromPartsRejectsInconsistentParts) {
  Result<MotionDatabase> db = WalkerBuilder().Build();
  ASSERT_TRUE(db.ok());
  MotionDatabase::Parts parts = db->parts();
  parts.clips[1].first_frame += 1;
  EXPECT_EQ(MotionDatabase::FromParts(parts).status().code(), ErrorCode::kInvalidData);
  parts = db->parts();
  parts.signals(3, 3) = NAN;
  EXPECT_FALSE(MotionDatabase::FromParts(parts).ok());
  parts = db->parts();
  parts.bands[0].values.conservativeResize(10, Eigen::NoChange);
  EXPECT_FALSE(MotionDatabase::FromParts(parts).ok());
  parts = db->parts();
  parts.correlation.entries[5].lag_frames = 99;
  EXPECT_FALSE(MotionDatabase::FromParts(parts).ok());
  EXPECT_TRUE(MotionDatabase::FromParts(db->parts()).ok());
}

}  // namespace
}  // namespace mocapfill
