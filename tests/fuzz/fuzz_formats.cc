// Fuzz targets of the motion file readers: BVH, glTF/GLB, .mfdb, .pca, FBX (Assimp in its
// child process) and the child's answer.
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include "formats/assimp/scene_wire.h"
#include "formats/bvh/bvh_reader.h"
#include "formats/gltf/gltf_reader.h"
#include "formats/mfdb/mfdb_file.h"
#include "formats/mfdb/xxhash64.h"
#include "formats/motion_io.h"
#include "formats/pca/pca_file.h"
#include "tests/fuzz/fuzz_targets.h"

namespace mocapfill::fuzz {
namespace {

std::string_view AsText(const uint8_t* data, size_t size) { return {reinterpret_cast<const char*>(data), size}; }

// A folder holding the external files a fuzzed glTF may name ("buffer.bin", "a.bin"), so
// that reading external buffers, and failing to, is exercised too. Made once per process and
// removed when it exits (libFuzzer ends with exit(), which runs static destructors).
class ExternalBufferFolder {
 public:
  ExternalBufferFolder()
      : dir_(std::filesystem::temp_directory_path() / ("mocapfill-fuzz-gltf-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(dir_);
    std::string bytes(4096, '\0');
    for (size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>((i * 37) & 0xff);
    for (const char* name : {"buffer.bin", "a.bin", "animation.bin"})
      std::ofstream(dir_ / name, std::ios::binary) << bytes;
  }
  ~ExternalBufferFolder() {
    std::error_code ec;
    std::filesystem::remove_all(dir_, ec);
  }
  std::string path() const { return dir_.string(); }

 private:
  std::filesystem::path dir_;
};

const std::string& GltfFolder() {
  static const ExternalBufferFolder folder;
  static const std::string path = folder.path();
  return path;
}

// The same bytes with a consistent header: both binary formats check magic, version, sizes
// and an XXH64 of the payload first, which random bytes almost never pass; patching them in
// lets the fuzzer reach the payload parser. Empty when the input is shorter than a header.
// Layout shared by .mfdb and .pca: magic[8], u32 version, u32 header size, u64 payload
// size, u64 payload hash (formats/mfdb/mfdb_file.h, formats/pca/pca_file.h).
std::string WithConsistentHeader(std::string_view bytes, const char (&magic)[9], uint32_t header_size) {
  if (bytes.size() < header_size) return {};
  std::string fixed(bytes);
  std::memcpy(fixed.data(), magic, 8);
  const uint32_t version = 1;
  const uint64_t payload_size = fixed.size() - header_size;
  Xxh64 hash;
  hash.Update(fixed.data() + header_size, payload_size);
  const uint64_t digest = hash.Digest();
  std::memcpy(fixed.data() + 8, &version, 4);
  std::memcpy(fixed.data() + 12, &header_size, 4);
  std::memcpy(fixed.data() + 16, &payload_size, 8);
  std::memcpy(fixed.data() + 24, &digest, 8);
  return fixed;
}

// The fixture FBX's scene as the child encodes it: the valid answer the wire target patches.
const std::string& EncodedFixtureScene() {
  static const std::string bytes = EncodeSceneResult(ImportFile(MOCAPFILL_FIXTURES_DIR "/fbx/pivot_chain.fbx"));
  return bytes;
}

}  // namespace

int FuzzBvh(const uint8_t* data, size_t size) {
  ImportOptions options;
  (void)ReadBvh(AsText(data, size), "fuzz.bvh", options);
  // Strict mode takes other paths through the same text.
  options.strict = true;
  (void)ReadBvh(AsText(data, size), "fuzz.bvh", options);
  return 0;
}

int FuzzGltf(const uint8_t* data, size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  const bool glb = size >= 4 && bytes.compare(0, 4, "glTF") == 0;
  (void)ReadGltf(bytes, GltfFolder() + (glb ? "/fuzz.glb" : "/fuzz.gltf"), ImportOptions{});
  return 0;
}

int FuzzFbx(const uint8_t* data, size_t size) {
  // A reader that hangs is stopped well inside libFuzzer's 10 s timeout; the scratch file
  // lives in the glTF target's folder, removed at exit.
  static const bool limited = setenv("MOCAPFILL_ASSIMP_TIMEOUT_S", "5", 1) == 0;
  (void)limited;
  const std::string path = GltfFolder() + "/fuzz.fbx";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  const Result<Scene> scene = ImportFile(path);
  // Inputs on which Assimp itself crashed (isolated, so no finding for libFuzzer) are kept
  // when asked, to become regression inputs (tests/fuzz/regressions/fbx/).
  const char* keep = std::getenv("MOCAPFILL_FUZZ_KEEP_ASSIMP_CRASHES");
  if (keep != nullptr && !scene.ok() && scene.status().message().find("reader crashed") != std::string::npos) {
    Xxh64 hash;
    hash.Update(data, size);
    std::ofstream(std::string(keep) + "/assimp-crash-" + std::to_string(hash.Digest()), std::ios::binary)
        .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  return 0;
}

int FuzzWire(const uint8_t* data, size_t size) {
  (void)DecodeSceneResult(AsText(data, size), "fuzz.fbx");
  // Patches of a valid answer reach the scene's inner fields: each 4 input bytes are a
  // position (2 bytes, modulo the length) and a value to XOR there.
  std::string patched = EncodedFixtureScene();
  if (patched.empty()) return 0;
  for (size_t i = 0; i + 3 < size; i += 4) {
    const size_t at = (static_cast<size_t>(data[i]) << 8 | data[i + 1]) % patched.size();
    patched[at] = static_cast<char>(patched[at] ^ data[i + 2]);
    if (data[i + 3] & 1) patched.resize(at);  // and cut there
    if (patched.empty()) break;
  }
  (void)DecodeSceneResult(patched, "fuzz.fbx");
  return 0;
}

int FuzzMfdb(const uint8_t* data, size_t size) {
  (void)ParseMfdb(AsText(data, size));
  const std::string fixed = WithConsistentHeader(AsText(data, size), "MFDB\r\n\x1a\n", 64);
  if (!fixed.empty()) (void)ParseMfdb(fixed);
  return 0;
}

int FuzzPca(const uint8_t* data, size_t size) {
  (void)ParsePcaModel(AsText(data, size));
  const std::string fixed = WithConsistentHeader(AsText(data, size), "MFPCA\r\n\x1a", 40);
  if (!fixed.empty()) (void)ParsePcaModel(fixed);
  return 0;
}

}  // namespace mocapfill::fuzz
