// Malformed glTF input: every file is rejected with kInvalidData (never a crash) and a
// message naming the file and the offending field.
#include <gtest/gtest.h>

#include <fstream>

#include "formats/file_io.h"
#include "formats/gltf/gltf_reader.h"
#include "formats/gltf/gltf_writer.h"
#include "tests/formats/gltf_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

struct BadFile {
  const char* file;
  const char* expected;  // part of the message naming the field
};

class GltfBadFixture : public ::testing::TestWithParam<BadFile> {};

TEST_P(GltfBadFixture, IsRejectedWithTheFieldNamed) {
  const std::string path = testing::FixturePath(std::string("bad/") + GetParam().file);
  Result<Scene> scene = testing::ReadGltfFile(path);
  ASSERT_FALSE(scene.ok());
  EXPECT_EQ(scene.status().code(), ErrorCode::kInvalidData) << scene.status().message();
  EXPECT_NE(scene.status().message().find(GetParam().file), std::string::npos) << scene.status().message();
  EXPECT_NE(scene.status().message().find(GetParam().expected), std::string::npos) << scene.status().message();
}

INSTANTIATE_TEST_SUITE_P(
    Fixtures, GltfBadFixture,
    ::testing::Values(BadFile{"garbage.glb", "GLB header: magic is not 'glTF'"},
                      BadFile{"truncated.glb", "GLB header: declared length 10048 bytes but the file has 5024"},
                      BadFile{"short_buffer.gltf", "buffers[0]: byteLength 120 but the data URI holds 60 bytes"},
                      BadFile{"out_of_range_accessor.gltf", "accessors[1]: buffer view 7 out of range"},
                      BadFile{"cyclic_nodes.gltf", "nodes[2]: is its own ancestor"},
                      BadFile{"nan_rotation.gltf", "animations[0].samplers[0].output: non-finite value"},
                      BadFile{"empty_animation.gltf", "animations[0].samplers[0].input: accessors[0]: count is 0"}),
    [](const ::testing::TestParamInfo<BadFile>& param) {
      std::string name = param.param.file;
      for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
      return name;
    });

// Edits a valid hand-made file's JSON text and checks the import error.
class GltfBadEdit : public ::testing::Test {
 protected:
  void SetUp() override {
    testing::SketchGltf sketch;
    const int hips = sketch.AddNode("Hips", -1);
    const int arm = sketch.AddNode("Arm", hips, {0.2, 0.4, 0});
    sketch.AddChannel("bend", arm, "rotation", {0.0f, 0.5f}, {0, 0, 0, 1, 0, 0, 1, 0});
    dir_ = testing::ScratchDir("gltf_bad_edit");
    ASSERT_TRUE(sketch.Write(dir_ + "/base.gltf"));
    text_ = *ReadFileBytes(dir_ + "/base.gltf");
  }

  // Replaces the first `from` by `to`, writes the result and imports it.
  Status Import(const std::string& from, const std::string& to, const ImportOptions& options = {}) {
    std::string text = text_;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    const std::string path = dir_ + "/edited.gltf";
    EXPECT_TRUE(WriteFileAtomic(path, text).ok());
    return testing::ReadGltfFile(path, options).status();
  }

  void ExpectInvalid(const Status& status, const std::string& expected) {
    EXPECT_EQ(status.code(), ErrorCode::kInvalidData) << status.message();
    EXPECT_NE(status.message().find("edited.gltf: " + expected), std::string::npos) << status.message();
  }

  std::string dir_, text_;
};

TEST_F(GltfBadEdit, TheBaseFileIsValid) { EXPECT_TRUE(Import("\"bend\"", "\"bend\"").ok()); }

TEST_F(GltfBadEdit, CyclicOrSharedNodes) {
  // Arm lists Hips as its child: Hips is its own ancestor.
  ExpectInvalid(Import("\"name\": \"Arm\",", "\"name\": \"Arm\", \"children\": [0],"), "nodes[0]: is its own ancestor");
  // Arm and a new node Other both list Hand (node 2) as a child.
  ExpectInvalid(Import("\"name\": \"Arm\",",
                       "\"name\": \"Arm\", \"children\": [2]}, {\"name\": \"Hand\"}, {\"name\": \"Other\", \"children\": [2],"),
                "nodes[2]: has two parents (nodes 1 and 3)");
  ExpectInvalid(Import("\"name\": \"Arm\",", "\"name\": \"Arm\", \"children\": [1],"), "nodes[1]: is its own child");
}

TEST_F(GltfBadEdit, ChildOutOfRange) { ExpectInvalid(Import("\"children\": [\n        1", "\"children\": [\n        9"), "nodes[0].children: node 9 out of range"); }

TEST_F(GltfBadEdit, AnimationWithoutChannels) {
  ExpectInvalid(Import("\"channels\": [", "\"channels\": [], \"unused\": ["), "animations[0]: no channels");
}

TEST_F(GltfBadEdit, DecreasingKeyTimes) {
  // The buffer starts with the key times 0 and 0.5; the first 12 base64 characters (9 bytes)
  // become 0.5f, 0.25f and the unchanged first byte of the rotations.
  const size_t uri = text_.find("base64,") + 7;
  ExpectInvalid(Import(text_.substr(uri, 12), "AAAAPwAAgD4A"),
                "animations[0].samplers[0].input: key times are not strictly increasing at key 1");
}

TEST_F(GltfBadEdit, AccessorLongerThanItsView) {
  ExpectInvalid(Import("\"count\": 2,\n      \"type\": \"VEC4\"", "\"count\": 3,\n      \"type\": \"VEC4\""),
                "animations[0].samplers[0].output: accessors[1]: 3 elements of 16 bytes");
}

TEST_F(GltfBadEdit, ChannelTargetOutOfRange) {
  ExpectInvalid(Import("\"node\": 1", "\"node\": 5"), "animations[0].channels[0].target.node: node 5 out of range");
}

TEST_F(GltfBadEdit, MissingExternalBuffer) {
  const size_t start = text_.find("\"uri\": \"");
  const size_t end = text_.find('"', start + 8);
  ExpectInvalid(Import(text_.substr(start, end - start + 1), "\"uri\": \"missing.bin\""),
                "buffers[0]: cannot read 'missing.bin'");
}

TEST_F(GltfBadEdit, ExternalBufferIsResolvedNextToTheFile) {
  // Move the embedded bytes to base.bin beside the file: the import reads them from there.
  const size_t start = text_.find("\"uri\": \"");
  const size_t end = text_.find('"', start + 8);
  const std::string uri = text_.substr(start + 8, end - start - 8);
  const std::string payload = uri.substr(uri.find(',') + 1);
  // Decode with the reader itself: a .gltf whose buffer is external must give the same clip.
  Result<Scene> embedded = testing::ReadGltfFile(dir_ + "/base.gltf");
  ASSERT_TRUE(embedded.ok()) << embedded.status().message();
  static const std::string kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string bytes;
  int bits = 0, value = 0;
  for (char c : payload) {
    if (c == '=') break;
    value = value << 6 | static_cast<int>(kAlphabet.find(c));
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      bytes += static_cast<char>((value >> bits) & 0xFF);
    }
  }
  ASSERT_TRUE(WriteFileAtomic(dir_ + "/base.bin", bytes).ok());
  EXPECT_TRUE(Import(uri, "base.bin").ok());
  Result<Scene> external = testing::ReadGltfFile(dir_ + "/edited.gltf");
  ASSERT_TRUE(external.ok()) << external.status().message();
  EXPECT_EQ(external->clips[0].rotations, embedded->clips[0].rotations);
  // A .bin shorter than byteLength is named with both sizes.
  ASSERT_TRUE(WriteFileAtomic(dir_ + "/base.bin", bytes.substr(0, 20)).ok());
  ExpectInvalid(Import(uri, "base.bin"), "buffers[0]: byteLength 40 but 'base.bin' has 20 bytes");
}

TEST_F(GltfBadEdit, NotJson) { ExpectInvalid(Import("\"asset\"", "asset"), "JSON: "); }

TEST(GltfBadInput, EveryTruncationOfAValidGlbFailsCleanly) {
  Result<std::string> glb = WriteGltf(testing::MakeDancerScene(), true, {});
  ASSERT_TRUE(glb.ok());
  int rejected = 0;
  for (size_t size = 0; size < glb->size(); size += 7) {
    Result<Scene> scene = ReadGltf(glb->substr(0, size), "cut.glb", {});
    ASSERT_FALSE(scene.ok()) << size;  // the GLB length field always exceeds a cut file
    EXPECT_EQ(scene.status().code(), ErrorCode::kInvalidData) << scene.status().message();
    ++rejected;
  }
  EXPECT_GT(rejected, 100);
}

TEST(GltfBadInput, CorruptedJsonBytesNeverCrash) {
  Result<std::string> gltf = WriteGltf(testing::MakeDancerScene(), false, {});
  ASSERT_TRUE(gltf.ok());
  // Flip digits and brackets through the JSON (not the base64 payload): each variant either
  // imports or fails with a Status, and ASan/UBSan builds watch for memory errors.
  const size_t payload = gltf->find("base64,");
  int failures = 0;
  for (size_t at = 0; at < payload; at += 13) {
    std::string text = *gltf;
    const char c = text[at];
    text[at] = std::isdigit(static_cast<unsigned char>(c)) ? '9' : c == '[' ? '{' : c == ']' ? '}' : c;
    Result<Scene> scene = ReadGltf(text, "flipped.gltf", {});
    if (!scene.ok()) ++failures;
  }
  EXPECT_GT(failures, 0);
}

}  // namespace
}  // namespace mocapfill
