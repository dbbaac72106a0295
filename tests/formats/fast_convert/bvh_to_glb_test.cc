// The streaming BVH-to-.glb converter (formats/fast_convert/bvh_to_glb.h) against the clip path (ReadBvh then
// WriteGlb): the same bytes for every shipped fixture and every corpus clip, on one thread
// and on two (including hemisphere flips at the split), and the clip path's behaviour
// wherever the import is not a plain one.
#include <gtest/gtest.h>

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "formats/fast_convert/rows_in_parallel.h"
#include "formats/bvh/bvh_reader.h"
#include "formats/fast_convert/bvh_to_glb.h"
#include "formats/fast_convert/file_text.h"
#include "formats/file_io.h"
#include "formats/gltf/gltf_writer.h"
#include "formats/motion_io.h"
#include "tests/formats/bvh_test_support.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

namespace fs = std::filesystem;
using testing::FixturePath;
using testing::EnlargeMotion;
using testing::ReadText;

std::optional<std::string> Streamed(const std::string& text, const std::string& path, int threads,
                                    ImportOptions options = {}, const ExportOptions& export_options = {}) {
  std::optional<fast_convert::StreamedGlb> glb = fast_convert::StreamBvhToGlb(text, path, options, export_options, threads);
  if (!glb) return std::nullopt;
  return glb->head + std::string(glb->tracks.view()) +
         std::string(reinterpret_cast<const char*>(glb->tail.data()), glb->tail.size());
}

Result<std::string> ThroughTheClip(const std::string& text, const std::string& path, ImportOptions options = {},
                                   const ExportOptions& export_options = {}) {
  ASSIGN_OR_RETURN(const Scene scene, ReadBvh(text, path, options));
  ASSIGN_OR_RETURN(const GlbFile glb, WriteGlb(scene, export_options));
  return glb.head + std::string(reinterpret_cast<const char*>(glb.bin.data()), glb.bin.size());
}

std::vector<std::string> FixtureBvhFiles() { return testing::FixtureFiles("bvh", ".bvh"); }

TEST(BvhGlbStream, EveryPlainFixtureGivesTheClipPathsBytes) {
  int streamed = 0;
  for (const std::string& path : FixtureBvhFiles()) {
    const std::string text = ReadText(path);
    const Result<std::string> expected = ThroughTheClip(text, path);
    ASSERT_TRUE(expected.ok()) << path << ": " << expected.status().message();
    const Result<Scene> scene = ReadBvh(text, path, {});
    ASSERT_TRUE(scene.ok());
    for (int threads : {1, 0}) {
      const std::optional<std::string> got = Streamed(text, path, threads);
      // Only an import with warnings (boxing_toes_short declares one frame too few) is left to the clip path.
      ASSERT_EQ(got.has_value(), scene->warnings.empty()) << path;
      if (!got) continue;
      EXPECT_EQ(*got, *expected) << path << " threads " << threads;
      ++streamed;
    }
  }
  EXPECT_EQ(streamed, 2 * 7);
}

// The skin and stick-figure mesh (ExportOptions::gltf_skeleton) follow the streamed tracks in
// the binary chunk; the file is still the clip path's, for every choice.
TEST(BvhGlbStream, SkinChoicesGiveTheClipPathsBytes) {
  int streamed = 0;
  for (const GltfSkeleton choice : {GltfSkeleton::kNodes, GltfSkeleton::kSkin, GltfSkeleton::kSkinAndMesh}) {
    ExportOptions export_options;
    export_options.gltf_skeleton = choice;
    for (const std::string& path : FixtureBvhFiles()) {
      const std::string text = ReadText(path);
      const Result<std::string> expected = ThroughTheClip(text, path, {}, export_options);
      ASSERT_TRUE(expected.ok()) << path << ": " << expected.status().message();
      const std::optional<std::string> got = Streamed(text, path, 0, {}, export_options);
      if (!got) continue;
      EXPECT_EQ(*got, *expected) << path << " choice " << static_cast<int>(choice);
      EXPECT_EQ(got->find("mocapfill_skeleton") != std::string::npos, choice != GltfSkeleton::kNodes) << path;
      ++streamed;
    }
  }
  EXPECT_EQ(streamed, 3 * 7);
}

TEST(BvhGlbStream, TwoThreadsGiveTheSerialBytes) {
  for (const char* name : {"cmu_01_01_short.bvh", "bandai_walk_normal_001_short.bvh", "cmu_mixed_orders.bvh",
                           "cmu_two_roots.bvh", "cmu_crlf.bvh"}) {
    const std::string text = EnlargeMotion(ReadText(FixturePath(std::string("bvh/") + name)), 4 * fast_convert::kParallelRowsMinBytes);
    const Result<std::string> expected = ThroughTheClip(text, "big.bvh");
    ASSERT_TRUE(expected.ok()) << name;
    const std::optional<std::string> serial = Streamed(text, "big.bvh", 1);
    const std::optional<std::string> parallel = Streamed(text, "big.bvh", 0);
    ASSERT_TRUE(serial && parallel) << name;
    EXPECT_EQ(*serial, *expected) << name;
    EXPECT_EQ(*parallel, *expected) << name;
  }
}

// A joint turning between +170 and -170 degrees every frame: the composed quaternions lie
// in opposite hemispheres from one frame to the next, so wherever the text is split, the
// second thread's chains start on the wrong side for one of the two sign conventions
// (rotation and packed value) and must be turned over at the join.
TEST(BvhGlbStream, HemisphereFlipsAtTheSplitAreJoinedExactly) {
  for (int extra_rows : {0, 1, 2, 3}) {
    std::string rows;
    int frames = 0;
    for (; rows.size() < 4 * fast_convert::kParallelRowsMinBytes + static_cast<size_t>(extra_rows) * 40; ++frames)
      rows += "1.5 90.25 -3.0 " + std::string(frames % 2 ? "170.0" : "-170.0") + " 10.0 " +
              std::to_string(frames % 7) + " 179.5 -179.5 0.0\n";
    const std::string text = "HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0 0\n  CHANNELS 6 Xposition Yposition Zposition "
                             "Zrotation Xrotation Yrotation\n  JOINT Spine\n  {\n    OFFSET 0 10 0\n    CHANNELS 3 "
                             "Zrotation Xrotation Yrotation\n    End Site\n    {\n      OFFSET 0 10 0\n    }\n  }\n}\n"
                             "MOTION\nFrames: " + std::to_string(frames) + "\nFrame Time: 0.0333333\n" + rows;
    const Result<std::string> expected = ThroughTheClip(text, "flips.bvh");
    ASSERT_TRUE(expected.ok()) << expected.status().message();
    const std::optional<std::string> parallel = Streamed(text, "flips.bvh", 0);
    ASSERT_TRUE(parallel.has_value());
    EXPECT_EQ(*parallel, *expected) << "extra rows " << extra_rows;
  }
}

// ConvertFile maps inputs of kMapFileMinBytes and more (formats/fast_convert/file_text.h). A text that
// ends exactly at a page boundary has no byte after it that a parser could read: the mapped
// conversion (whole pages, nothing beyond) must write what the clip path writes.
TEST(BvhGlbStream, MappedInputEndingOnAPageBoundaryConvertsAsTheClipPath) {
  std::string text = EnlargeMotion(ReadText(FixturePath("bvh/cmu_01_01_short.bvh")), kMapFileMinBytes + 1);
  constexpr size_t kPage = 4096;
  // Spaces after the last row's newline, then a last newline on the page's final byte.
  const size_t padded = (text.size() + 1 + kPage - 1) / kPage * kPage;
  text.append(padded - text.size() - 1, ' ');
  text += '\n';
  ASSERT_EQ(text.size() % kPage, 0u);
  const std::string dir = testing::TestOutputDir("bvh_glb_mapped");
  const std::string input = dir + "/page_end.bvh";
  ASSERT_TRUE(WriteFileAtomic(input, text).ok());
  const Result<FileText> mapped = ReadFileText(input);
  ASSERT_TRUE(mapped.ok());
  EXPECT_TRUE(mapped->mapped());
  const ConvertResult converted = ConvertFile(input, dir + "/page_end.glb", {}, {});
  ASSERT_TRUE(converted.status.ok()) << converted.status.message();
  const Result<std::string> expected = ThroughTheClip(text, input);
  ASSERT_TRUE(expected.ok());
  EXPECT_EQ(ReadText(dir + "/page_end.glb"), *expected);
  const Result<Scene> imported = ImportFile(input);
  ASSERT_TRUE(imported.ok()) << imported.status().message();
  EXPECT_EQ(imported->clips.at(0).num_frames, ReadBvh(text, input, {})->clips.at(0).num_frames);
}

// A single conversion leaves its input to the process's exit and so maps inputs from
// kMapLeftInputMinBytes (formats/fast_convert/file_text.h): every shipped BVH converts to the same bytes
// that way as read into memory, and as through the clip, one ending on a page boundary too.
TEST(BvhGlbStream, InputsLeftToExitAreMappedAndConvertAsTheClipPath) {
  const std::string dir = testing::TestOutputDir("bvh_glb_left_to_exit");
  ConvertOptions left;
  left.leave_input_to_exit = true;
  std::vector<std::string> inputs;
  for (const auto& entry : fs::directory_iterator(FixturePath("bvh"))) inputs.push_back(entry.path().string());
  std::string page_text = ReadText(FixturePath("bvh/cmu_crlf.bvh"));
  page_text.append((page_text.size() + 4096) / 4096 * 4096 - page_text.size() - 1, ' ');
  page_text += '\n';
  ASSERT_EQ(page_text.size() % 4096, 0u);
  inputs.push_back(dir + "/page_end.bvh");
  ASSERT_TRUE(WriteFileAtomic(inputs.back(), page_text).ok());
  size_t mapped = 0, large_enough = 0;
  for (const std::string& input : inputs) {
    const std::string name = fs::path(input).stem().string();
    const Result<FileText> text = ReadFileText(input, kMapLeftInputMinBytes);
    ASSERT_TRUE(text.ok());
    mapped += text->mapped();
    large_enough += fs::file_size(input) >= kMapLeftInputMinBytes;
    const ConvertResult read = ConvertFile(input, dir + "/" + name + "_read.glb", {}, {});
    const ConvertResult left_mapped = ConvertFile(input, dir + "/" + name + "_left.glb", {}, {}, left);
    ASSERT_TRUE(read.status.ok() && left_mapped.status.ok()) << input;
    EXPECT_EQ(left_mapped.warnings, read.warnings) << input;
    const std::string left_bytes = ReadText(dir + "/" + name + "_left.glb");
    EXPECT_EQ(left_bytes, ReadText(dir + "/" + name + "_read.glb")) << input;
    const Result<std::string> expected = ThroughTheClip(ReadText(input), input);
    ASSERT_TRUE(expected.ok());
    EXPECT_EQ(left_bytes, *expected) << input;
  }
  EXPECT_EQ(mapped, large_enough);
  EXPECT_GE(mapped, 6u);
}

// Whatever the clip path would warn about or reject, and Z-up sources, are left to it, so
// that ConvertFile reports and writes exactly what ImportFile and ExportFile do.
TEST(BvhGlbStream, AnythingButAPlainImportIsLeftToTheClipPath) {
  const std::string path = FixturePath("bvh/cmu_01_01_short.bvh");
  const std::string text = ReadText(path);
  ImportOptions z_up;
  z_up.up = "z";
  EXPECT_FALSE(Streamed(text, path, 0, z_up).has_value());
  ImportOptions bad_unit;
  bad_unit.unit = "furlong";
  EXPECT_FALSE(Streamed(text, path, 0, bad_unit).has_value());
  EXPECT_FALSE(Streamed(ReadText(FixturePath("bvh/boxing_toes_short.bvh")), "toes.bvh", 0).has_value());
  for (const char* bad : {"truncated.bvh", "nan_value.bvh", "inf_value.bvh", "wrong_channel_count.bvh",
                          "unknown_channel.bvh", "zero_frames.bvh", "absurd_frames.bvh", "garbage.bvh",
                          "missing_brace.bvh"}) {
    const std::string bad_path = FixturePath(std::string("bad/") + bad);
    EXPECT_FALSE(Streamed(ReadText(bad_path), bad_path, 0).has_value()) << bad;
  }
  // A declared frame count off by one either way.
  const std::string more = EnlargeMotion(text, 1000);
  const size_t frames_at = more.find("Frames: ") + 8;
  const int frames = std::stoi(more.substr(frames_at));
  for (int delta : {-1, 1}) {
    std::string off = more;
    off.replace(frames_at, std::to_string(frames).size(), std::to_string(frames + delta));
    EXPECT_FALSE(Streamed(off, path, 0).has_value()) << delta;
  }

  const std::string dir = testing::TestOutputDir("bvh_glb");
  ImportOptions strict;
  strict.strict = true;
  const ConvertResult warned = ConvertFile(FixturePath("bvh/boxing_toes_short.bvh"), dir + "/toes.glb", {}, {});
  ASSERT_TRUE(warned.status.ok());
  ASSERT_EQ(warned.warnings.size(), 1u);
  EXPECT_NE(warned.warnings[0].find("Frames declares 79 frames"), std::string::npos);
  const ConvertResult refused = ConvertFile(FixturePath("bvh/boxing_toes_short.bvh"), dir + "/strict.glb", strict, {});
  EXPECT_EQ(refused.status.code(), ErrorCode::kInvalidData);
  EXPECT_FALSE(refused.failed_writing);
  EXPECT_FALSE(fs::exists(dir + "/strict.glb"));
  const ConvertResult turned = ConvertFile(path, dir + "/z_up.glb", z_up, {});
  ASSERT_TRUE(turned.status.ok());
  const Result<Scene> scene = ReadBvh(text, path, z_up);
  ASSERT_TRUE(scene.ok());
  const Result<GlbFile> glb = WriteGlb(*scene, {});
  ASSERT_TRUE(glb.ok());
  EXPECT_EQ(ReadText(dir + "/z_up.glb"),
            glb->head + std::string(reinterpret_cast<const char*>(glb->bin.data()), glb->bin.size()));
  const ConvertResult unwritable = ConvertFile(path, dir + "/no/such/folder/out.glb", {}, {});
  EXPECT_EQ(unwritable.status.code(), ErrorCode::kIoError);
  EXPECT_TRUE(unwritable.failed_writing);
}

TEST(BvhGlbStream, EveryCorpusClipGivesTheClipPathsBytes) {
  MOCAPFILL_REQUIRE_CORPUS();
  std::vector<std::string> files = testing::CorpusFiles("bandai-namco-1/data", ".bvh");
  for (const std::string& f : testing::CorpusFiles("cmu", ".bvh")) files.push_back(f);
  for (const std::string& f : testing::CorpusFiles("assimp", ".bvh")) files.push_back(f);
  ASSERT_GE(files.size(), 177u);
  int streamed = 0;
  const std::string dir = testing::ScratchDir("bvh_glb_corpus");
  for (const std::string& path : files) {
    const std::string text = ReadText(path);
    const Result<std::string> expected = ThroughTheClip(text, path);
    ASSERT_TRUE(expected.ok()) << path;
    const std::optional<std::string> got = Streamed(text, path, 0);
    if (got) {
      EXPECT_EQ(*got, *expected) << path;
      ++streamed;
    }
    const ConvertResult converted = ConvertFile(path, dir + "/out.glb", {}, {});
    ASSERT_TRUE(converted.status.ok()) << path;
    EXPECT_EQ(ReadText(dir + "/out.glb"), *expected) << path;
  }
  EXPECT_EQ(streamed, static_cast<int>(files.size()) - 1);  // Boxing_Toes.bvh warns (3,069 declared, 3,070 rows)
}

}  // namespace
}  // namespace mocapfill
