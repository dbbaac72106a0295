// Real motion through the glTF writer and reader: every shipped BVH fixture (CMU,
// Bandai-Namco, Assimp cuts and layout variants) exported as .glb and read back.
#include <gtest/gtest.h>

#include <filesystem>

#include "formats/bvh/bvh_reader.h"
#include "formats/file_io.h"
#include "tests/formats/gltf_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> BvhFixtures() { return testing::FixtureFiles("bvh", ".bvh"); }

class GltfFromBvh : public ::testing::TestWithParam<std::string> {};

TEST_P(GltfFromBvh, GlbKeepsSkeletonClipAndProvenance) {
  const std::string stem = fs::path(GetParam()).stem().string();
  Result<std::string> text = ReadFileBytes(GetParam());
  ASSERT_TRUE(text.ok());
  Result<Scene> bvh = ReadBvh(*text, GetParam(), {});
  ASSERT_TRUE(bvh.ok()) << bvh.status().message();
  for (const char* ext : {".glb", ".gltf"}) {
    Result<std::string> path = testing::WriteGltfOutput(*bvh, "bvh_" + stem + ext);
    ASSERT_TRUE(path.ok()) << path.status().message();
    Result<Scene> back = testing::ReadGltfFile(*path);
    ASSERT_TRUE(back.ok()) << back.status().message();
    testing::ExpectScenesMatch(*bvh, *back);
    EXPECT_EQ(back->source.source_frame_time_s, bvh->source.source_frame_time_s);
  }
}

INSTANTIATE_TEST_SUITE_P(Fixtures, GltfFromBvh, ::testing::ValuesIn(BvhFixtures()),
                         [](const ::testing::TestParamInfo<std::string>& param) {
                           std::string name = fs::path(param.param).stem().string();
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace mocapfill
