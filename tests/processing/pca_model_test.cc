// PCA model building, projection and component edits on Bandai-Namco walks.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "processing/core/rotation.h"
#include "processing/pca/pca_clip.h"
#include "processing/pca/pca_edit.h"
#include "processing/pca/pca_model_builder.h"
#include "processing/pca/pca_projection.h"
#include "tests/processing/pca_test_data.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

using testing::BandaiClipPath;
using testing::BandaiPathsExcept;
using testing::BuildBandaiDatabase;
using testing::ImportBandaiClip;

// Every component has unit length and is orthogonal to the others up to rounding.
constexpr double kOrthonormalTolerance = 1e-9;
// Reconstruction errors are compared in weighted units (cm-like); "equal" means rounding.
constexpr double kRoundingCm = 1e-9;

PcaModel BuildWalkModel(const std::string& held_out_style, PcaModelOptions options) {
  Result<MotionDatabase> db = BuildBandaiDatabase(BandaiPathsExcept("walk", held_out_style));
  EXPECT_TRUE(db.ok()) << db.status().message();
  if (!db.ok()) return {};
  Result<PcaModel> model = BuildPcaModel(*db, options);
  EXPECT_TRUE(model.ok()) << model.status().message();
  return model.ok() ? *model : PcaModel{};
}

// The held-out clip as weighted pose vectors of `model`.
Eigen::MatrixXd HeldOutPoses(const PcaModel& model, const std::string& style) {
  Result<Scene> scene = ImportBandaiClip(BandaiClipPath("walk", style));
  EXPECT_TRUE(scene.ok()) << scene.status().message();
  Result<PcaBinding> binding = BindPcaModel(model, scene->skeleton);
  EXPECT_TRUE(binding.ok()) << binding.status().message();
  return EncodeClip(model, *binding, scene->skeleton, scene->clips[0]).poses;
}

TEST(PcaModel, OptionsValidateNamesEachBadField) {
  PcaModelOptions options;
  EXPECT_TRUE(options.Validate().ok());
  options.basis.variance_kept = 0.0;
  EXPECT_NE(options.Validate().message().find("variance_kept"), std::string::npos);
  options = {};
  options.basis.variance_kept = 1.5;
  EXPECT_EQ(options.Validate().code(), ErrorCode::kInvalidArgument);
  options = {};
  options.basis.max_components = 0;
  EXPECT_NE(options.Validate().message().find("max_components"), std::string::npos);
  options = {};
  options.basis.window_frames = 0;
  EXPECT_NE(options.Validate().message().find("window_frames"), std::string::npos);
  options = {};
  options.basis.window_stride_frames = 0;
  EXPECT_NE(options.Validate().message().find("window_stride_frames"), std::string::npos);
  options = {};
  options.root_rate_horizon_s = -1.0;
  EXPECT_NE(options.Validate().message().find("root_rate_horizon_s"), std::string::npos);
  options = {};
  options.labels = {"style="};
  EXPECT_NE(options.Validate().message().find("labels"), std::string::npos);
}

TEST(PcaModel, WalkModelKeepsNinetyFivePercentWithFewestComponents) {
  MOCAPFILL_REQUIRE_CORPUS();
  const PcaModel model = BuildWalkModel("normal", {});
  ASSERT_TRUE(model.Validate().ok()) << model.Validate().message();
  const int k = model.num_components();
  EXPECT_EQ(model.num_joints(), 22);
  EXPECT_EQ(model.pose_dim(), 3 * 22 + 4);
  EXPECT_GE(ExplainedVarianceRatio(model, k), 0.95);
  EXPECT_LT(ExplainedVarianceRatio(model, k - 1), 0.95);
  EXPECT_LE(k, 30);
  const Eigen::MatrixXd gram = model.components.transpose() * model.components;
  EXPECT_LT((gram - Eigen::MatrixXd::Identity(k, k)).cwiseAbs().maxCoeff(), kOrthonormalTolerance);
  for (int i = 1; i < k; ++i) EXPECT_GE(model.variances[i - 1], model.variances[i]);
  // 28 walk clips of 14 styles (two takes each).
  EXPECT_EQ(model.clips.size(), 28u);
  std::printf("walk model: %d components for 95%% of the variance, %d frames\n", k, model.num_samples);
}

TEST(PcaModel, ReconstructionErrorFallsMonotonicallyWithComponents) {
  MOCAPFILL_REQUIRE_CORPUS();
  PcaModelOptions options;
  options.basis.variance_kept = 1.0;
  options.basis.max_components = 40;
  const PcaModel model = BuildWalkModel("normal", options);
  ASSERT_EQ(model.num_components(), 40);
  const Eigen::MatrixXd held_out = HeldOutPoses(model, "normal");
  double previous = ReconstructionRms(model, held_out, 0);
  std::printf("held-out walk_normal_001 reconstruction RMS (weighted cm): k=0 %.3f", previous);
  for (int k = 1; k <= model.num_components(); ++k) {
    const double rms = ReconstructionRms(model, held_out, k);
    // Nested orthogonal projections can only remove error.
    EXPECT_LE(rms, previous + kRoundingCm) << "k = " << k;
    if (k % 5 == 0) std::printf(", k=%d %.3f", k, rms);
    previous = rms;
  }
  std::printf("\n");
  // The held-out style is still a walk: 10 components explain most of it.
  EXPECT_LT(ReconstructionRms(model, held_out, 10), 0.5 * ReconstructionRms(model, held_out, 0));
}

TEST(PcaModel, LabelsSelectBehaviourSpecificClips) {
  MOCAPFILL_REQUIRE_CORPUS();
  std::vector<std::string> paths = BandaiPathsExcept("walk", "normal");
  paths.resize(4);
  const std::vector<std::string> runs = BandaiPathsExcept("run", "normal");
  paths.insert(paths.end(), runs.begin(), runs.begin() + 4);
  Result<MotionDatabase> db = BuildBandaiDatabase(paths);
  ASSERT_TRUE(db.ok()) << db.status().message();
  PcaModelOptions options;
  options.labels = {"run"};
  Result<PcaModel> runs_only = BuildPcaModel(*db, options);
  ASSERT_TRUE(runs_only.ok()) << runs_only.status().message();
  EXPECT_EQ(runs_only->clips.size(), 4u);
  for (const std::string& name : runs_only->clips) EXPECT_NE(name.find("run"), std::string::npos) << name;
  options.labels = {"content=walk", "run"};
  EXPECT_EQ(BuildPcaModel(*db, options)->clips.size(), 8u);
  options.labels = {"style=walk"};  // walk is a content, not a style
  EXPECT_EQ(BuildPcaModel(*db, options).status().code(), ErrorCode::kInvalidArgument);
}

TEST(PcaEdit, ZeroDialsAreTheIdentity) {
  MOCAPFILL_REQUIRE_CORPUS();
  const PcaModel model = BuildWalkModel("normal", {});
  const Eigen::MatrixXd poses = HeldOutPoses(model, "normal");
  PcaEditOptions options;
  options.dials = {{0, 0.0}, {2, 0.0}};
  Result<Eigen::MatrixXd> edited = EditPoses(model, poses, options);
  ASSERT_TRUE(edited.ok()) << edited.status().message();
  EXPECT_EQ((*edited - poses).cwiseAbs().maxCoeff(), 0.0);
}

TEST(PcaEdit, DialMovesOnlyItsComponentByStandardDeviations) {
  MOCAPFILL_REQUIRE_CORPUS();
  const PcaModel model = BuildWalkModel("normal", {});
  const Eigen::MatrixXd poses = HeldOutPoses(model, "normal");
  PcaEditOptions options;
  options.dials = {{1, 2.0}};
  Result<Eigen::MatrixXd> edited = EditPoses(model, poses, options);
  ASSERT_TRUE(edited.ok()) << edited.status().message();
  const Eigen::MatrixXd delta = ProjectOntoModel(model, *edited) - ProjectOntoModel(model, poses);
  for (int k = 0; k < model.num_components(); ++k) {
    const double expected = k == 1 ? 2.0 * std::sqrt(model.variances[1]) : 0.0;
    EXPECT_NEAR(delta.col(k).maxCoeff(), expected, 1e-9) << k;
    EXPECT_NEAR(delta.col(k).minCoeff(), expected, 1e-9) << k;
  }
  // The residual outside the model is untouched.
  const Eigen::MatrixXd residual_before = poses - ReconstructFromModel(model, ProjectOntoModel(model, poses));
  const Eigen::MatrixXd residual_after = *edited - ReconstructFromModel(model, ProjectOntoModel(model, *edited));
  EXPECT_LT((residual_after - residual_before).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(PcaEdit, WindowModelZeroDialsAreTheIdentity) {
  MOCAPFILL_REQUIRE_CORPUS();
  PcaModelOptions options;
  options.basis.window_frames = 8;
  options.basis.window_stride_frames = 4;
  const PcaModel model = BuildWalkModel("normal", options);
  ASSERT_EQ(model.dim(), 8 * model.pose_dim());
  const Eigen::MatrixXd poses = HeldOutPoses(model, "normal");
  PcaEditOptions edit;
  edit.dials = {{0, 0.0}};
  Result<Eigen::MatrixXd> same = EditPoses(model, poses, edit);
  ASSERT_TRUE(same.ok()) << same.status().message();
  EXPECT_LT((*same - poses).cwiseAbs().maxCoeff(), 1e-9);
  edit.dials = {{0, 1.5}};
  Result<Eigen::MatrixXd> moved = EditPoses(model, poses, edit);
  ASSERT_TRUE(moved.ok());
  EXPECT_GT((*moved - poses).cwiseAbs().maxCoeff(), 1.0);  // a 1.5-sigma move is visible (cm)
}

TEST(PcaEdit, ValidateRejectsBadDials) {
  MOCAPFILL_REQUIRE_CORPUS();
  const PcaModel model = BuildWalkModel("normal", {});
  PcaEditOptions options;
  options.dials = {{model.num_components(), 1.0}};
  EXPECT_NE(options.Validate(model).message().find("out of range"), std::string::npos);
  options.dials = {{0, 1.0}, {0, 2.0}};
  EXPECT_NE(options.Validate(model).message().find("twice"), std::string::npos);
  options.dials = {{0, 3.5}};
  EXPECT_EQ(options.Validate(model).code(), ErrorCode::kInvalidArgument);
  options.dials = {{0, std::nan("")}};
  EXPECT_EQ(options.Validate(model).code(), ErrorCode::kInvalidArgument);
  const Eigen::MatrixXd wrong = Eigen::MatrixXd::Zero(10, model.pose_dim() - 1);
  options.dials = {};
  EXPECT_EQ(EditPoses(model, wrong, options).status().code(), ErrorCode::kInvalidArgument);
}

TEST(PcaEdit, ClipRoundTripThroughZeroEditKeepsEveryRotation) {
  MOCAPFILL_REQUIRE_CORPUS();
  const PcaModel model = BuildWalkModel("normal", {});
  Result<Scene> scene = ImportBandaiClip(BandaiClipPath("walk", "normal"));
  ASSERT_TRUE(scene.ok());
  const MotionClip& clip = scene->clips[0];
  Result<PcaBinding> binding = BindPcaModel(model, scene->skeleton);
  ASSERT_TRUE(binding.ok());
  const EncodedClip encoded = EncodeClip(model, *binding, scene->skeleton, clip);
  Result<MotionClip> decoded = DecodeClip(model, *binding, scene->skeleton, encoded, encoded.poses, clip);
  ASSERT_TRUE(decoded.ok()) << decoded.status().message();
  double worst_deg = 0.0, worst_m = 0.0;
  for (int f = 0; f < clip.num_frames; ++f)
    for (int j = 0; j < clip.num_joints; ++j) {
      worst_deg = std::max(worst_deg, GeodesicAngle(clip.rotation(f, j), decoded->rotation(f, j)) * kDegPerRad);
      worst_m = std::max(worst_m, (clip.translation(f, j) - decoded->translation(f, j)).norm());
    }
  EXPECT_LT(worst_deg, 1e-6);
  EXPECT_LT(worst_m, 1e-9);
}

}  // namespace
}  // namespace mocapfill
