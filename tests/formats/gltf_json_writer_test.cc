// The glTF JSON writer (formats/gltf/gltf_json_writer.cc), checked without a second writer:
//  - what it writes reads back, through tinygltf's loader, as the model the exporter built,
//    member by member (gltf_internal::CheckWrittenModelReadsBack): .glb, and .gltf indented
//    and compact; bare nodes, the generated skin, the stick-figure mesh; every shipped
//    fixture and, when present, every corpus file;
//  - its text is canonical: nlohmann's dump of the parsed text is the text itself (keys in
//    sorted order, shortest round-trip numbers, standard escapes, two-space indentation),
//    the layout our files have always had, so that a change of layout shows here.
// The fixtures' files are kept under <build>/test-output/gltf for the validator pass.
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "formats/file_io.h"
#include "formats/gltf/gltf_readback_check.h"
#include "formats/gltf/gltf_writer.h"
#include "formats/motion_io.h"
#include "tests/formats/gltf_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

constexpr GltfSkeleton kSkeletons[] = {GltfSkeleton::kNodes, GltfSkeleton::kSkin, GltfSkeleton::kSkinAndMesh};

std::string GlbJsonChunk(const std::string& glb) {
  uint32_t length = 0;
  std::memcpy(&length, glb.data() + 12, 4);
  std::string text = glb.substr(20, length);
  while (!text.empty() && text.back() == ' ') text.pop_back();  // the chunk's padding
  return text;
}

// "" when `text` is nlohmann's dump of itself (indented by `indent`, or compact for -1),
// else where the two part (the texts are too long to print whole).
std::string NotCanonical(const std::string& text, int indent, const std::string& ending = "") {
  const std::string canonical = nlohmann::json::parse(text).dump(indent) + ending;
  if (canonical == text) return "";
  size_t at = 0;
  while (at < text.size() && at < canonical.size() && text[at] == canonical[at]) ++at;
  const size_t from = at < 60 ? 0 : at - 60;
  return "not canonical from byte " + std::to_string(at) + ": written \"" + text.substr(from, 120) +
         "\", canonical \"" + canonical.substr(from, 120) + "\"";
}

std::string Describe(const std::string& what, GltfSkeleton skeleton, const char* format) {
  return what + " (" + format + ", skeleton option " + std::to_string(static_cast<int>(skeleton)) + ")";
}

// The .glb and both .gltf layouts of `scene` read back as built and are canonical text.
// `keep_as`: also write the files under test-output/gltf with this name stem.
void ExpectWrittenRight(const Scene& scene, const std::string& what, GltfSkeleton skeleton,
                        const std::string& keep_as = "") {
  ExportOptions options;
  options.gltf_skeleton = skeleton;
  const std::string glb_what = Describe(what, skeleton, "glb");
  const Status glb_back = gltf_internal::CheckWrittenModelReadsBack(scene, true, options);
  EXPECT_TRUE(glb_back.ok()) << glb_what << ": " << glb_back.message();
  const Result<std::string> glb = WriteGltf(scene, true, options);
  ASSERT_TRUE(glb.ok()) << glb_what;
  EXPECT_EQ(NotCanonical(GlbJsonChunk(*glb), -1), "") << glb_what;
  for (const bool pretty : {true, false}) {
    options.pretty = pretty;
    const std::string gltf_what = Describe(what, skeleton, pretty ? "indented gltf" : "compact gltf");
    const Status gltf_back = gltf_internal::CheckWrittenModelReadsBack(scene, false, options);
    EXPECT_TRUE(gltf_back.ok()) << gltf_what << ": " << gltf_back.message();
    const Result<std::string> gltf = WriteGltf(scene, false, options);
    ASSERT_TRUE(gltf.ok()) << gltf_what;
    EXPECT_EQ(NotCanonical(*gltf, pretty ? 2 : -1, "\n"), "") << gltf_what;
    if (!keep_as.empty() && pretty) {
      ASSERT_TRUE(WriteFileAtomic(testing::GltfOutputPath(keep_as + ".gltf"), *gltf).ok());
    }
  }
  if (!keep_as.empty()) {
    ASSERT_TRUE(WriteFileAtomic(testing::GltfOutputPath(keep_as + ".glb"), *glb).ok());
  }
}

std::vector<std::string> MotionFiles(const std::vector<std::string>& folders, bool corpus) {
  std::vector<std::string> files;
  for (const std::string& folder : folders)
    for (const char* ext : {".bvh", ".glb", ".gltf", ".fbx"})
      for (const std::string& f : corpus ? testing::CorpusFiles(folder, ext) : testing::FixtureFiles(folder, ext))
        files.push_back(f);
  return files;
}

TEST(GltfJsonWriter, EveryFixtureReadsBackAsWritten) {
  const std::vector<std::string> files = MotionFiles({"bvh", "gltf", "fbx", "sketches", "rigs"}, false);
  ASSERT_GE(files.size(), 17u);
  for (const std::string& path : files) {
    const Result<Scene> scene = ImportFile(path);
    ASSERT_TRUE(scene.ok()) << path << ": " << scene.status().message();
    const std::string stem = "json_writer_" + std::filesystem::path(path).stem().string();
    for (const GltfSkeleton skeleton : kSkeletons)
      ExpectWrittenRight(*scene, path, skeleton, skeleton == GltfSkeleton::kSkinAndMesh ? stem : "");
  }
}

TEST(GltfJsonWriter, EveryCorpusFileReadsBackAsWritten) {
  MOCAPFILL_REQUIRE_CORPUS();
  const std::vector<std::string> files = MotionFiles({"bandai-namco-1/data", "cmu", "assimp", "geno"}, true);
  ASSERT_GE(files.size(), 185u);
  for (const std::string& path : files) {
    const Result<Scene> scene = ImportFile(path);
    ASSERT_TRUE(scene.ok()) << path << ": " << scene.status().message();
    ExpectWrittenRight(*scene, path, GltfSkeleton::kSkin);
  }
}

// Names that need escaping or are not ASCII, several clips (one with sparse keys), extras
// with an empty array, materials at and off their defaults, meshes with and without skins.
TEST(GltfJsonWriter, OddStringsAndDefaultsReadBackAsWritten) {
  Result<Scene> sketch = ImportFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  ASSERT_TRUE(sketch.ok());
  sketch->clips.push_back(sketch->clips[0]);
  sketch->clips[1].name = "quote \" backslash \\ tab \t delete \x7f é";
  sketch->skeleton.mutable_joint(1).bvh_channels.clear();
  sketch->skeleton.mutable_joint(2).name = "ü\nnewline";
  for (const GltfSkeleton skeleton : kSkeletons) ExpectWrittenRight(*sketch, "odd strings", skeleton);

  Scene dancer = testing::MakeDancerScene();
  for (Mesh& mesh : dancer.meshes)
    for (MeshPrimitive& p : mesh.primitives) p.base_color = Eigen::Vector4f(1, 1, 1, 1);
  ExpectWrittenRight(dancer, "white materials", GltfSkeleton::kSkin, "json_writer_white_dancer");
  const Result<std::string> gltf = WriteGltf(dancer, false, {});
  ASSERT_TRUE(gltf.ok());
  const nlohmann::json parsed = nlohmann::json::parse(*gltf);
  ASSERT_FALSE(parsed["materials"].empty());
  for (const nlohmann::json& material : parsed["materials"]) EXPECT_FALSE(material.contains("pbrMetallicRoughness"));
}

}  // namespace
}  // namespace mocapfill
