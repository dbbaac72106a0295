// Hostile sizes, generated at test time: each input is read within a memory bound
// or refused with exit 2 and a message naming the file; nothing is killed, nothing hangs
// (each run has a time limit). The bounds are the ones the README documents.
#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <filesystem>
#include <vector>

#include "tests/support/cli_run.h"
#include "tests/support/test_paths.h"

// Under AddressSanitizer the mocapfill being run carries its shadow memory and quarantine:
// its peak memory says nothing about the tool's, so only the outcome is checked there.
#if defined(__SANITIZE_ADDRESS__)
#define MOCAPFILL_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MOCAPFILL_UNDER_ASAN 1
#endif
#endif
#ifdef MOCAPFILL_UNDER_ASAN
constexpr bool kMeasuresMemory = false;
#else
constexpr bool kMeasuresMemory = true;
#endif

namespace mocapfill {
namespace {

struct LimitedRun : testing::FinishedRun {
  std::string output;  // stdout and stderr
};

// Runs `mocapfill args...`, killed after `limit_s` seconds.
LimitedRun RunLimited(const std::vector<std::string>& args, const std::string& scratch, int limit_s) {
  const std::string log = scratch + "/run.log";
  LimitedRun run;
  static_cast<testing::FinishedRun&>(run) = testing::WaitCli(testing::StartCli(args, log), limit_s);
  run.output = testing::ReadAll(log);
  return run;
}

// The CMU fixture's hierarchy, its MOTION header declaring `frames`.
std::string CmuHierarchy() {
  std::ifstream in(testing::FixturePath("bvh/cmu_01_01_short.bvh"));
  const std::string text(std::istreambuf_iterator<char>(in), {});
  return text.substr(0, text.find("MOTION"));
}

std::string CmuRow() {
  std::ifstream in(testing::FixturePath("bvh/cmu_01_01_short.bvh"));
  const std::string text(std::istreambuf_iterator<char>(in), {});
  const size_t first = text.find('\n', text.find("Frame Time")) + 1;
  return text.substr(first, text.find('\n', first) + 1 - first);
}

// A gigabyte of valid rows: refused once the motion passes the 20 million joint-frames every
// reader accepts, with the memory that limit documents (56 bytes per joint-frame): declared
// as it is (refused before a row is read), and understated as one frame (refused at the
// limit, its rows reserved once from the lines the file holds rather than grown by doubling).
TEST(HostileInput, GigabyteOfBvhRowsIsRefusedWithinTheMemoryBound) {
  const std::string dir = testing::ScratchDir("hostile_gigabyte");
  const std::string path = dir + "/gigabyte.bvh";
  const std::string row = CmuRow();
  const size_t rows = (size_t{1} << 30) / row.size() + 1;
  const auto frames_line = [](size_t frames) {
    std::string line = "Frames: " + std::to_string(frames);
    return line + std::string(20 - line.size(), ' ') + "\n";  // one length for every count
  };
  const size_t header_at = CmuHierarchy().size() + std::string("MOTION\n").size();
  {
    std::ofstream out(path, std::ios::binary);
    out << CmuHierarchy() << "MOTION\n" << frames_line(rows) << "Frame Time: .0083333\n";
    std::string block;
    for (int i = 0; i < 4096; ++i) block += row;
    for (size_t written = 0; written < rows; written += 4096) out << block;
  }
  for (const size_t declared : {rows, size_t{1}}) {
    SCOPED_TRACE("Frames: " + std::to_string(declared));
    {
      std::fstream patch(path, std::ios::binary | std::ios::in | std::ios::out);
      patch.seekp(static_cast<std::streamoff>(header_at));
      patch << frames_line(declared);
    }
    const LimitedRun run = RunLimited({"convert", path, dir + "/out.glb"}, dir, 300);
    EXPECT_FALSE(run.timed_out);
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find(path), std::string::npos) << run.output;
    EXPECT_NE(run.output.find("too large"), std::string::npos) << run.output;
    if (kMeasuresMemory) {
      // The documented bound: the input file's bytes (1 GiB here), plus 1.1 GB for 20 million
      // joint-frames when rows are read (the understated file; a doubling vector would take
      // 2.9 GB).
      EXPECT_LT(run.max_rss_mb, declared == 1 ? 2300 : 1200);
    }
    EXPECT_FALSE(std::ifstream(dir + "/out.glb").good());
    RecordProperty(declared == 1 ? "max_rss_mb_understated" : "max_rss_mb_declared", static_cast<int>(run.max_rss_mb));
  }
  std::remove(path.c_str());
}

// "Frames: 1000000000" over ten rows: the declaration reserves nothing it cannot see.
TEST(HostileInput, BillionDeclaredFramesReserveNothing) {
  const std::string dir = testing::ScratchDir("hostile_declared_frames");
  const std::string path = dir + "/declared.bvh";
  {
    std::ofstream out(path, std::ios::binary);
    out << CmuHierarchy() << "MOTION\nFrames: 1000000000\nFrame Time: .0083333\n";
    for (int i = 0; i < 10; ++i) out << CmuRow();
  }
  const LimitedRun run = RunLimited({"convert", path, dir + "/out.glb"}, dir, 60);
  EXPECT_FALSE(run.timed_out);
  EXPECT_TRUE(run.exit_code == 0 || run.exit_code == 2) << run.output;
  EXPECT_NE(run.output.find("1000000000"), std::string::npos) << "the mismatch is reported: " << run.output;
  if (kMeasuresMemory) {
    EXPECT_LT(run.max_rss_mb, 200);
  }
}

// A chain of a million joints: refused by the joint limit before any motion is read.
TEST(HostileInput, MillionJointsAreRefused) {
  const std::string dir = testing::ScratchDir("hostile_joints");
  const std::string path = dir + "/joints.bvh";
  constexpr int kJoints = 1'000'000;
  {
    std::ofstream out(path, std::ios::binary);
    out << "HIERARCHY\nROOT j0\n{\nOFFSET 0 0 0\nCHANNELS 6 Xposition Yposition Zposition Zrotation Yrotation "
           "Xrotation\n";
    for (int j = 1; j < kJoints; ++j)
      out << "JOINT j" << j << "\n{\nOFFSET 0 1 0\nCHANNELS 3 Zrotation Yrotation Xrotation\n";
    out << "End Site\n{\nOFFSET 0 1 0\n}\n";
    for (int j = 0; j < kJoints; ++j) out << "}\n";
    out << "MOTION\nFrames: 1\nFrame Time: 0.033333\n";
    for (int c = 0; c < 3 * kJoints + 3; ++c) out << "0 ";
    out << "\n";
  }
  const LimitedRun run = RunLimited({"convert", path, dir + "/out.glb"}, dir, 120);
  EXPECT_FALSE(run.timed_out);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(path), std::string::npos) << run.output;
  EXPECT_NE(run.output.find("joints"), std::string::npos) << run.output;
  if (kMeasuresMemory) {
    EXPECT_LT(run.max_rss_mb, 500);
  }
}

// An accessor claiming 2^31 elements over a small buffer.
TEST(HostileInput, GltfAccessorCountOf2To31IsRefused) {
  const std::string dir = testing::ScratchDir("hostile_gltf_count");
  const std::string path = dir + "/count.gltf";
  std::ofstream(path) << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],
    "nodes": [{"name": "root"}],
    "buffers": [{"byteLength": 8, "uri": "data:application/octet-stream;base64,AAAAAAAAgD8="}],
    "bufferViews": [{"buffer": 0, "byteLength": 8}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 2147483648, "type": "SCALAR",
                   "min": [0], "max": [1]},
                  {"bufferView": 0, "componentType": 5126, "count": 2147483648, "type": "VEC4"}],
    "animations": [{"channels": [{"sampler": 0, "target": {"node": 0, "path": "rotation"}}],
                    "samplers": [{"input": 0, "output": 1}]}]})";
  const LimitedRun run = RunLimited({"convert", path, dir + "/out.glb"}, dir, 60);
  EXPECT_FALSE(run.timed_out);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(path), std::string::npos) << run.output;
  if (kMeasuresMemory) {
    EXPECT_LT(run.max_rss_mb, 200);
  }
}

// A glTF of `accessors` accessors (each a small valid object), written in large pieces.
void WriteGltfOfAccessors(const std::string& path, int accessors) {
  std::ofstream out(path, std::ios::binary);
  out << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"name": "root"}],
    "buffers": [{"byteLength": 8, "uri": "data:application/octet-stream;base64,AAAAAAAAgD8="}],
    "bufferViews": [{"buffer": 0, "byteLength": 8}], "accessors": [)";
  const std::string one = R"({"bufferView":0,"componentType":5126,"count":2,"type":"SCALAR"})";
  std::string block;
  for (int i = 0; i < 10'000; ++i) block += one + ",";
  for (int written = 0; written + 10'000 < accessors; written += 10'000) out << block;
  for (int i = 0; i < accessors % 10'000 + (accessors % 10'000 == 0 ? 10'000 : 0); ++i) out << (i ? "," : "") << one;
  out << "]}";
}

// Past a million JSON objects a glTF is refused before any parse (tinygltf would hold about
// 1.1 KB per accessor: ten million take 11 GB).
void ExpectGltfRefusedForItsSize(const std::string& test, int accessors, long max_rss_mb) {
  const std::string dir = testing::ScratchDir(test);
  const std::string path = dir + "/accessors.gltf";
  WriteGltfOfAccessors(path, accessors);
  const LimitedRun run = RunLimited({"convert", path, dir + "/out.glb"}, dir, 120);
  EXPECT_FALSE(run.timed_out);
  EXPECT_EQ(run.exit_code, 2) << run.output;
  EXPECT_NE(run.output.find(path + ": JSON: " + std::to_string(accessors + 6) + " objects; at most 1000000"),
            std::string::npos)
      << run.output;
  EXPECT_FALSE(std::filesystem::exists(dir + "/out.glb"));
  if (kMeasuresMemory) {
    EXPECT_LT(run.max_rss_mb, max_rss_mb);  // the mapped file's pages count; nothing else grows
  }
}

TEST(HostileInput, GltfOfAMillionObjectsIsRefusedBeforeParsing) {
  ExpectGltfRefusedForItsSize("hostile_gltf_million", 1'000'000, 200);
}

TEST(HostileInput, GltfOfTenMillionAccessorsIsRefusedWithinTheMemoryBound) {
  ExpectGltfRefusedForItsSize("hostile_gltf_ten_million", 10'000'000, 900);
}

// Assimp reads in a child process: one that runs out of time or memory ends as exit 2
// naming the file, and writes nothing.
TEST(HostileInput, AssimpOutOfTimeOrMemoryExitsTwoNamingTheFile) {
  const std::string dir = testing::ScratchDir("hostile_assimp");
  const std::string fbx = testing::FixturePath("fbx/animation_with_skeleton.fbx");
  struct Case {
    const char* variable;
    const char* value;
    const char* says;
  };
  std::vector<Case> cases = {{"MOCAPFILL_ASSIMP_TIMEOUT_S", "0.000001", "took longer than 1e-06 s on this file"}};
  // Out of memory ends in Assimp's own bad_alloc error or in an abort (fixture: the latter).
  if (kMeasuresMemory) cases.push_back({"MOCAPFILL_ASSIMP_MEMORY_MB", "1", "(limit 1 MiB; MOCAPFILL_ASSIMP_MEMORY_MB sets it)"});
  for (const Case& c : cases) {
    setenv(c.variable, c.value, 1);
    const LimitedRun run = RunLimited({"convert", fbx, dir + "/out.glb"}, dir, 60);
    unsetenv(c.variable);
    EXPECT_EQ(run.exit_code, 2) << c.variable << ": " << run.output;
    EXPECT_NE(run.output.find(fbx + ": the Assimp reader "), std::string::npos) << run.output;
    EXPECT_NE(run.output.find(c.says), std::string::npos) << run.output;
    const bool memory = std::string(c.variable).find("MEMORY") != std::string::npos;
    EXPECT_NE(run.output.find(memory ? "memory" : "took longer"), std::string::npos) << run.output;
    EXPECT_FALSE(std::filesystem::exists(dir + "/out.glb"));
  }
}

// GLB chunk lengths near 2^32: the sums overflow 32 bits.
TEST(HostileInput, GlbChunkLengthsThatOverflowAreRefused) {
  const std::string dir = testing::ScratchDir("hostile_glb_chunks");
  for (uint32_t json_length : {0xFFFFFFF0u, 0xFFFFFFFCu, 0x80000000u}) {
    const std::string path = dir + "/chunks.glb";
    std::string bytes = "glTF";
    auto u32 = [&bytes](uint32_t v) { bytes.append(reinterpret_cast<const char*>(&v), 4); };
    u32(2);
    u32(64);  // total length: what the file really holds
    u32(json_length);
    u32(0x4E4F534Au);  // "JSON"
    bytes += R"({"asset":{"version":"2.0"}})";
    bytes.resize(64, ' ');
    std::ofstream(path, std::ios::binary) << bytes;
    const LimitedRun run = RunLimited({"convert", path, dir + "/out.gltf"}, dir, 60);
    EXPECT_FALSE(run.timed_out);
    EXPECT_EQ(run.exit_code, 2) << json_length << ": " << run.output;
    EXPECT_NE(run.output.find(path), std::string::npos) << run.output;
    if (kMeasuresMemory) {
      EXPECT_LT(run.max_rss_mb, 200);
    }
  }
}

// A rig map of a million entries: parsed within a bounded memory and refused by name (none
// of its joints is in the sketch).
TEST(HostileInput, MillionEntryRigMapIsRefusedNamingAJoint) {
  const std::string dir = testing::ScratchDir("hostile_map");
  const std::string map = dir + "/map.json";
  {
    std::ofstream out(map);
    out << "{";
    for (int i = 0; i < 1'000'000; ++i) out << (i ? ",\n" : "") << "\"joint_" << i << "\": \"leftUpperLeg\"";
    out << "}";
  }
  const LimitedRun run =
      RunLimited({"rig", "show", testing::FixturePath("bvh/cmu_01_01_short.bvh"), "--map", map}, dir, 120);
  EXPECT_FALSE(run.timed_out);
  EXPECT_NE(run.exit_code, 0) << run.output;
  EXPECT_NE(run.exit_code, -1) << run.output;
  EXPECT_NE(run.output.find("joint_"), std::string::npos) << run.output;
  if (kMeasuresMemory) {
    EXPECT_LT(run.max_rss_mb, 1000);
  }
}

}  // namespace
}  // namespace mocapfill
