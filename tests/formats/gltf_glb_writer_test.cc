// The .glb writer hands the file over in two pieces (WriteGlb: header and JSON chunk, then
// the binary chunk) so that ExportFile writes the animation from where it was built. The
// pieces must form one consistent file: the framing is checked here, and the whole file
// reads back as the model that was written.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>

#include "formats/file_io.h"
#include "formats/gltf/gltf_readback_check.h"
#include "formats/gltf/gltf_writer.h"
#include "formats/motion_io.h"
#include "tests/formats/gltf_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

uint32_t U32At(const std::string& bytes, size_t offset) {
  uint32_t v = 0;
  std::memcpy(&v, bytes.data() + offset, 4);
  return v;
}

std::string Joined(const GlbFile& glb) {
  return glb.head + std::string(reinterpret_cast<const char*>(glb.bin.data()), glb.bin.size());
}

void ExpectConsistentGlb(const GlbFile& glb) {
  const std::string file = Joined(glb);
  ASSERT_GE(file.size(), 20u);
  EXPECT_EQ(file.substr(0, 4), "glTF");
  EXPECT_EQ(U32At(file, 4), 2u);
  EXPECT_EQ(U32At(file, 8), file.size());
  const uint32_t json_length = U32At(file, 12);
  EXPECT_EQ(U32At(file, 16), 0x4E4F534Au);
  EXPECT_EQ(json_length % 4, 0u);
  const nlohmann::json json_chunk = nlohmann::json::parse(file.substr(20, json_length));
  EXPECT_EQ(glb.bin.size() % 4, 0u);
  if (glb.bin.empty()) {
    EXPECT_EQ(glb.head.size(), file.size());
    EXPECT_FALSE(json_chunk.contains("buffers"));
    return;
  }
  EXPECT_EQ(glb.head.size(), 20u + json_length + 8u);
  EXPECT_EQ(U32At(file, 20 + json_length), glb.bin.size());
  EXPECT_EQ(U32At(file, 24 + json_length), 0x004E4942u);
  ASSERT_EQ(json_chunk["buffers"].size(), 1u);
  EXPECT_EQ(json_chunk["buffers"][0]["byteLength"].get<size_t>(), glb.bin.size());
}

TEST(GlbWriter, PiecesFormOneFileThatReadsBack) {
  const Scene scene = testing::MakeDancerScene();  // skeleton, clips, meshes and skins
  Result<GlbFile> glb = WriteGlb(scene, {});
  ASSERT_TRUE(glb.ok()) << glb.status().message();
  ExpectConsistentGlb(*glb);
  Result<std::string> whole = WriteGltf(scene, true, {});
  ASSERT_TRUE(whole.ok());
  EXPECT_EQ(*whole, Joined(*glb));
  const Status read_back = gltf_internal::CheckWrittenModelReadsBack(scene, true);
  EXPECT_TRUE(read_back.ok()) << read_back.message();
}

TEST(GlbWriter, ExportFileWritesThePieces) {
  const std::string bvh_path = testing::FixturePath("sketches/walk_proud_002_legs8.bvh");
  Result<Scene> scene = ImportFile(bvh_path);
  ASSERT_TRUE(scene.ok()) << scene.status().message();
  Result<GlbFile> glb = WriteGlb(*scene, {});
  ASSERT_TRUE(glb.ok()) << glb.status().message();
  ExpectConsistentGlb(*glb);
  const std::string path = testing::GltfOutputPath("walk_proud_002_legs8_pieces.glb");
  ASSERT_TRUE(ExportFile(*scene, path).ok());
  Result<std::string> written = ReadFileBytes(path);
  ASSERT_TRUE(written.ok());
  EXPECT_EQ(*written, Joined(*glb));
  const Status read_back = gltf_internal::CheckWrittenModelReadsBack(*scene, true);
  EXPECT_TRUE(read_back.ok()) << read_back.message();
}

TEST(GlbWriter, SkeletonWithoutClipsHasNoBinaryChunk) {
  Scene scene = testing::MakeDancerScene();
  scene.clips.clear();
  scene.meshes.clear();
  scene.skins.clear();
  // Bare nodes: the default skin's inverse bind matrices would fill a binary chunk.
  ExportOptions bare;
  bare.gltf_skeleton = GltfSkeleton::kNodes;
  Result<GlbFile> glb = WriteGlb(scene, bare);
  ASSERT_TRUE(glb.ok()) << glb.status().message();
  EXPECT_TRUE(glb->bin.empty());
  ExpectConsistentGlb(*glb);
  Result<std::string> whole = WriteGltf(scene, true, bare);
  ASSERT_TRUE(whole.ok());
  EXPECT_EQ(*whole, glb->head);
  // With the skin: its matrices are the whole binary chunk.
  Result<GlbFile> skinned = WriteGlb(scene, {});
  ASSERT_TRUE(skinned.ok());
  EXPECT_EQ(skinned->bin.size(), 64u * scene.skeleton.num_joints());
  ExpectConsistentGlb(*skinned);
}

}  // namespace
}  // namespace mocapfill
