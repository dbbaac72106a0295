// Real-data tests of the database, pyramid and filter: the shipped fixtures always, the
// Bandai-Namco corpus (../shared/data) when present.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "formats/mfdb/mfdb_file.h"
#include "formats/mfdb/motion_folder.h"
#include "formats/motion_io.h"
#include "processing/analysis/band_energy.h"
#include "processing/database/motion_database_builder.h"
#include "processing/database/stored_clips.h"
#include "processing/filtering/motion_filter.h"
#include "tests/processing/synthetic_motion.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

constexpr double kExactRad = 1e-9;  // reconstruction error below 1e-9 on real clips

Scene Import(const std::string& path) {
  Result<Scene> scene = ImportFile(path);
  EXPECT_TRUE(scene.ok()) << path << ": " << scene.status().message();
  return scene.ok() ? std::move(scene).value() : Scene{};
}

std::vector<std::string> RealClips() {
  std::vector<std::string> files = {testing::FixturePath("bvh/bandai_walk_normal_001_short.bvh"),
                                    testing::FixturePath("bvh/cmu_01_01_short.bvh")};
  for (const char* name : {"dataset-1_walk-left_old_001.bvh", "dataset-1_kick_normal_001.bvh",
                           "dataset-1_dance-short_normal_001.bvh"}) {
    const std::string path = testing::DataPath(std::string("bandai-namco-1/data/") + name);
    if (!testing::DataDir().empty()) files.push_back(path);
  }
  return files;
}

TEST(RealMotion, PyramidReconstructionIsExactOnTangentCoordinates) {
  for (const std::string& path : RealClips()) {
    const Scene scene = Import(path);
    ASSERT_FALSE(scene.clips.empty()) << path;
    const MotionClip& clip = scene.clips[0];
    const MotionClip* clips[] = {&clip};
    const TangentReference reference = ComputeTangentReference(scene.skeleton, clips, FindMotionRoot(scene.skeleton, clips));
    const ClipSignals signals = DecomposeClip(scene.skeleton, clip, reference);
    Eigen::MatrixXd all(clip.num_frames, signals.tangent.cols() + signals.root_features.cols());
    all << signals.tangent, signals.root_features;
    Result<Pyramid> pyramid = BuildPyramid(all, clip.sample_rate_hz, {});
    ASSERT_TRUE(pyramid.ok());
    EXPECT_GE(pyramid->levels(), 5) << path;
    const Eigen::MatrixXd back = Reconstruct(*pyramid, {}).value();
    EXPECT_LT((back - all).cwiseAbs().maxCoeff(), kExactRad) << path;
    // A band's energy scales by the gain squared.
    BandGains gains;
    gains.band_gains = {1.0, 1.0, 1.0, 1.7};
    const Eigen::MatrixXd edited = Reconstruct(*pyramid, gains).value();
    const Eigen::MatrixXd band = edited - (all - pyramid->bands[3]);
    const std::vector<std::vector<int>> everything = {[&] {
      std::vector<int> cols(all.cols());
      for (int c = 0; c < all.cols(); ++c) cols[c] = c;
      return cols;
    }()};
    const double e3 = BandEnergies(*pyramid, everything)(0, 3);
    EXPECT_GT(e3, 0.0);
    EXPECT_NEAR(band.squaredNorm() / clip.num_frames, 1.7 * 1.7 * e3, 1e-9 * e3) << path;
  }
}

TEST(RealMotion, FilterWithUnitGainsIsExactAndEditedExportIsValid) {
  const std::string out_dir = testing::TestOutputDir("filter");
  for (const std::string& path : RealClips()) {
    Scene scene = Import(path);
    ASSERT_FALSE(scene.clips.empty());
    const MotionClip original = scene.clips[0];
    MultiresFilterOptions options;
    Result<MotionClip> same = MultiresFilter(scene.skeleton, original, options);
    ASSERT_TRUE(same.ok()) << same.status().message();
    EXPECT_LT(testing::MaxRotationError(original, *same), kExactRad) << path;
    EXPECT_LT(testing::MaxTranslationError(original, *same), 1e-9) << path;
    // Thesis-style edit: raise the middle bands.
    options.gains.band_gains = {1.0, 1.0, 1.5, 1.5};
    Result<MotionClip> lively = MultiresFilter(scene.skeleton, original, options);
    ASSERT_TRUE(lively.ok());
    EXPECT_GT(testing::MaxRotationError(original, *lively), 1.0 * kRadPerDeg) << path;
    scene.clips[0] = std::move(lively).value();
    const std::string stem = std::filesystem::path(path).stem().string();
    const std::string out = out_dir + "/" + stem + "_mid_bands_x1.5.glb";
    ASSERT_TRUE(ExportFile(scene, out).ok()) << out;
    Scene back = Import(out);
    ASSERT_EQ(back.clips.size(), 1u);
    EXPECT_EQ(back.clips[0].num_frames, original.num_frames);
  }
}

// The 30 Bandai-Namco walk clips (content "walk", all styles).
std::vector<std::string> WalkFiles() {
  std::vector<std::string> walks;
  for (const std::string& f : testing::CorpusFiles("bandai-namco-1/data", ".bvh"))
    if (f.find("dataset-1_walk_") != std::string::npos) walks.push_back(f);
  return walks;
}

Result<MotionDatabase> BuildFrom(const std::vector<std::string>& files, int threads) {
  ASSIGN_OR_RETURN(std::vector<LabeledScene> scenes, ImportMotionFiles(files, {}, threads));
  DatabaseOptions options;
  options.threads = threads;
  MotionDatabaseBuilder builder(options);
  for (LabeledScene& s : scenes) {
    s.scene.clips[0].name = s.labels["name"];
    RETURN_IF_ERROR(builder.Add(s.scene.skeleton, std::move(s.scene.clips[0]), s.labels));
  }
  return builder.Build();
}

TEST(BandaiNamco, WalkCorrelationsShowWhatTheThesisRelies) {
  MOCAPFILL_REQUIRE_CORPUS();
  const std::vector<std::string> walks = WalkFiles();
  ASSERT_EQ(walks.size(), 30u);
  Result<MotionDatabase> db = BuildFrom(walks, 0);
  ASSERT_TRUE(db.ok()) << db.status().message();
  EXPECT_EQ(db->skeleton().name(db->root_joint()), "Hips");
  EXPECT_EQ(db->clip(0).labels.at("content"), "walk");
  const CorrelationTable& table = db->correlation();
  ASSERT_EQ(table.band, 3);  // the stride band at 30 Hz
  auto entry = [&](const std::string& a, int axis_a, const std::string& b, int axis_b) {
    return table.at(TangentColumn(*db->skeleton().Find(a), axis_a), TangentColumn(*db->skeleton().Find(b), axis_b));
  };
  // Left and right hips swing in anti-phase: strong, at (almost) zero lag.
  const CorrelationEntry legs = entry("UpperLeg_L", 1, "UpperLeg_R", 1);
  EXPECT_GT(legs.max_abs, 0.85f);
  EXPECT_LE(std::abs(legs.lag_frames), 1);
  // Pelvis against hip (thesis figure 4.4).
  const CorrelationEntry pelvis = entry("Hips", 2, "UpperLeg_R", 2);
  EXPECT_GT(pelvis.max_abs, 0.7f);
  EXPECT_LE(std::abs(pelvis.lag_frames), 1);
  // Unrelated joints: weak.
  EXPECT_LT(entry("Neck", 2, "Hand_R", 0).max_abs, 0.25f);
  std::vector<float> across;
  for (int a = 0; a < 3 * db->num_joints(); ++a)
    for (int b = 0; b < 3 * db->num_joints(); ++b)
      if (a / 3 != b / 3 && table.at(a, b).max_abs > 0.0f) across.push_back(table.at(a, b).max_abs);
  std::nth_element(across.begin(), across.begin() + across.size() / 2, across.end());
  EXPECT_LT(across[across.size() / 2], 0.45f);  // median |corr| between different joints
  // The static joint_Root never correlates.
  EXPECT_EQ(entry("joint_Root", 0, "UpperLeg_L", 1).max_abs, 0.0f);
}

TEST(BandaiNamco, BuildIsDeterministicAndRoundTripsThroughAFile) {
  MOCAPFILL_REQUIRE_CORPUS();
  std::vector<std::string> files = WalkFiles();
  files.resize(10);
  Result<MotionDatabase> one = BuildFrom(files, 1);
  Result<MotionDatabase> two = BuildFrom(files, 2);
  ASSERT_TRUE(one.ok() && two.ok());
  const std::string bytes = SerializeMfdb(*one);
  EXPECT_EQ(bytes, SerializeMfdb(*two));  // same bytes whatever the thread count
  const std::string path = testing::ScratchDir("bandai_mfdb") + "/walks.mfdb";
  ASSERT_TRUE(WriteMfdb(*one, path).ok());
  Result<MotionDatabase> loaded = ReadMfdb(path);
  ASSERT_TRUE(loaded.ok()) << loaded.status().message();
  for (int i = 0; i < one->num_clips(); ++i) {
    const MotionClip a = ReconstructClip(*one, i).value();
    const MotionClip b = ReconstructClip(*loaded, i).value();
    EXPECT_TRUE(a.rotations == b.rotations && a.translations == b.translations) << one->clip(i).name;
  }
  // The stored clip is the imported clip up to float32 storage.
  const Scene scene = Import(files[3]);
  const MotionClip stored = ReconstructClip(*loaded, 3).value();
  EXPECT_LT(testing::MaxRotationError(scene.clips[0], stored), 1e-5);
  EXPECT_LT(testing::MaxTranslationError(scene.clips[0], stored), 1e-4);
}

}  // namespace
}  // namespace mocapfill
