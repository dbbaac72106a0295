// Corpus round trips over every BVH of the shared data:
//  - BVH -> glb -> BVH keeps every rotation (geodesic < 1e-4 deg) and translation (< 1e-5 m),
//    writes Euler angles in the source's channel order, continuous over time;
//  - world joint positions by FK of the BVH and, independently, of the glb agree within 0.01 mm.
// The glb files are kept under <build>/test-output/corpus for the CI validator pass.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>

#include "formats/file_io.h"
#include "formats/motion_io.h"
#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "tests/support/gltf_reference_fk.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

namespace fs = std::filesystem;

constexpr double kRotationToleranceDeg = 1e-4;
constexpr double kTranslationToleranceM = 1e-5;
constexpr double kWorldPositionToleranceM = 1e-5;  // 0.01 mm

std::string OutputDir() { return testing::TestOutputDir("corpus"); }

// Largest jump between consecutive frames of any rotation channel in the BVH text.
double MaxEulerJumpDeg(const std::string& bvh_text, const Skeleton& skeleton) {
  std::vector<bool> is_rotation;
  for (const Joint& joint : skeleton.joints())
    for (const std::string& c : joint.bvh_channels) is_rotation.push_back(c.find("rotation") != std::string::npos);
  std::istringstream in(bvh_text.substr(bvh_text.find("Frame Time")));
  std::string line;
  std::getline(in, line);
  std::vector<double> previous;
  double max_jump = 0.0;
  while (std::getline(in, line)) {
    std::istringstream row(line);
    std::vector<double> values;
    double v;
    while (row >> v) values.push_back(v);
    if (values.size() != is_rotation.size()) continue;
    if (!previous.empty())
      for (size_t c = 0; c < values.size(); ++c)
        if (is_rotation[c]) max_jump = std::max(max_jump, std::abs(values[c] - previous[c]));
    previous = values;
  }
  return max_jump;
}

class CorpusRoundTrip : public ::testing::TestWithParam<std::string> {};

TEST(CorpusRoundTripSetup, CorpusHasTheExpectedBvhFiles) {
  MOCAPFILL_REQUIRE_CORPUS();
  EXPECT_EQ(testing::CorpusFiles("bandai-namco-1", ".bvh").size(), 174u);
  EXPECT_EQ(testing::CorpusFiles("cmu", ".bvh").size(), 2u);
  EXPECT_EQ(testing::CorpusFiles("assimp", ".bvh").size(), 1u);
}

TEST_P(CorpusRoundTrip, BvhToGlbToBvhKeepsEveryRotationAndTranslation) {
  MOCAPFILL_REQUIRE_CORPUS();
  const std::string path = GetParam();
  const std::string stem = fs::path(path).stem().string();
  Result<Scene> source = ImportFile(path);
  ASSERT_TRUE(source.ok()) << source.status().message();
  const std::string glb = OutputDir() + "/" + stem + ".glb";
  ASSERT_TRUE(ExportFile(*source, glb).ok());
  Result<Scene> via_glb = ImportFile(glb);
  ASSERT_TRUE(via_glb.ok()) << via_glb.status().message();
  const std::string bvh = testing::ScratchDir("corpus_" + stem) + "/" + stem + ".bvh";
  ASSERT_TRUE(ExportFile(*via_glb, bvh).ok());
  Result<Scene> back = ImportFile(bvh);
  ASSERT_TRUE(back.ok()) << back.status().message();

  const Skeleton& s = source->skeleton;
  ASSERT_EQ(back->skeleton.num_joints(), s.num_joints());
  const MotionClip& a = source->clips.at(0);
  const MotionClip& b = back->clips.at(0);
  ASSERT_EQ(a.num_frames, b.num_frames);
  EXPECT_EQ(a.sample_rate_hz, b.sample_rate_hz);
  double worst_angle_deg = 0.0, worst_translation_m = 0.0;
  for (int j = 0; j < s.num_joints(); ++j) {
    EXPECT_EQ(back->skeleton.name(j), s.name(j));
    EXPECT_EQ(back->skeleton.joint(j).bvh_channels, s.joint(j).bvh_channels) << s.name(j);
    for (int f = 0; f < a.num_frames; ++f) {
      worst_angle_deg = std::max(worst_angle_deg, GeodesicAngle(a.rotation(f, j), b.rotation(f, j)) * kDegPerRad);
      worst_translation_m = std::max(worst_translation_m, (a.translation(f, j) - b.translation(f, j)).norm());
    }
  }
  EXPECT_LT(worst_angle_deg, kRotationToleranceDeg) << stem;
  EXPECT_LT(worst_translation_m, kTranslationToleranceM) << stem;
  const std::string text = *ReadFileBytes(bvh);
  EXPECT_LT(MaxEulerJumpDeg(text, back->skeleton), 180.0) << stem << ": Euler angles jump by 360 degrees";
}

TEST_P(CorpusRoundTrip, WorldPositionsOfBvhAndGlbAgreeIndependently) {
  MOCAPFILL_REQUIRE_CORPUS();
  const std::string path = GetParam();
  const std::string stem = fs::path(path).stem().string();
  Result<Scene> source = ImportFile(path);
  ASSERT_TRUE(source.ok()) << source.status().message();
  const std::string glb = testing::ScratchDir("corpus_fk_" + stem) + "/" + stem + ".glb";
  ASSERT_TRUE(ExportFile(*source, glb).ok());
  testing::ReferenceGltfAnimation reference;
  std::string error;
  ASSERT_TRUE(testing::EvaluateGltfReference(glb, reference, error)) << error;
  const MotionClip& clip = source->clips.at(0);
  ASSERT_EQ(static_cast<int>(reference.times.size()), clip.num_frames);
  const std::vector<Eigen::Vector3d> ours = ComputeWorldPositions(source->skeleton, clip);
  double worst = 0.0;
  for (int j = 0; j < clip.num_joints; ++j) {
    const auto node = std::find(reference.node_names.begin(), reference.node_names.end(), source->skeleton.name(j));
    ASSERT_NE(node, reference.node_names.end()) << source->skeleton.name(j);
    const size_t n = node - reference.node_names.begin();
    for (int f = 0; f < clip.num_frames; ++f)
      worst = std::max(worst, (ours[static_cast<size_t>(f) * clip.num_joints + j] - reference.world_positions[f][n]).norm());
  }
  EXPECT_LT(worst, kWorldPositionToleranceM) << stem << ": worst joint position difference " << worst * 1000 << " mm";
}

std::vector<std::string> AllCorpusBvh() {
  std::vector<std::string> files = testing::CorpusFiles("", ".bvh");
  if (files.empty()) files.push_back("");  // one visible skip instead of an empty suite
  return files;
}

std::string TestName(const ::testing::TestParamInfo<std::string>& info) {
  std::string name = info.param.empty() ? "no_corpus" : fs::path(info.param).stem().string();
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(AllBvh, CorpusRoundTrip, ::testing::ValuesIn(AllCorpusBvh()), TestName);

}  // namespace
}  // namespace mocapfill
