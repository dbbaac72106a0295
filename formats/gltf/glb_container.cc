#include "formats/gltf/glb_container.h"

#include <cstdint>
#include <cstdio>
#include <string>

namespace mocapfill::gltf_internal {

namespace {

constexpr uint32_t kChunkJson = 0x4E4F534A;  // "JSON" read as a little-endian uint32
constexpr uint32_t kChunkBin = 0x004E4942;   // "BIN\0"
constexpr size_t kHeaderBytes = 12;
constexpr size_t kChunkHeaderBytes = 8;

uint32_t ReadU32(std::string_view bytes, size_t offset) {
  const auto* p = reinterpret_cast<const unsigned char*>(bytes.data() + offset);
  return uint32_t{p[0]} | uint32_t{p[1]} << 8 | uint32_t{p[2]} << 16 | uint32_t{p[3]} << 24;
}

std::string Hex(uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof(text), "0x%08X", value);
  return text;
}

std::string FirstBytes(std::string_view bytes) {
  std::string text;
  for (size_t i = 0; i < bytes.size() && i < 4; ++i) {
    char hex[8];
    std::snprintf(hex, sizeof(hex), "%s%02X", i ? " " : "", static_cast<unsigned char>(bytes[i]));
    text += hex;
  }
  return text;
}

}  // namespace

bool HasGlbMagic(std::string_view bytes) { return bytes.size() >= 4 && bytes.substr(0, 4) == "glTF"; }

Result<GlbParts> ParseGlbContainer(std::string_view bytes) {
  if (bytes.size() < kHeaderBytes)
    return InvalidData("GLB header: the file has " + std::to_string(bytes.size()) +
                       " bytes, a GLB needs at least 12 (magic, version, length)");
  if (!HasGlbMagic(bytes))
    return InvalidData("GLB header: magic is not 'glTF' (first bytes " + FirstBytes(bytes) +
                       "): not a binary glTF file");
  const uint32_t version = ReadU32(bytes, 4);
  if (version != 2) return InvalidData("GLB header: version " + std::to_string(version) + ", expected 2");
  const uint32_t length = ReadU32(bytes, 8);
  if (length > bytes.size())
    return InvalidData("GLB header: declared length " + std::to_string(length) + " bytes but the file has " +
                       std::to_string(bytes.size()) + " (truncated file?)");
  if (length < kHeaderBytes + kChunkHeaderBytes)
    return InvalidData("GLB header: declared length " + std::to_string(length) + " bytes leaves no room for the JSON chunk");
  const std::string_view glb = bytes.substr(0, length);

  const uint64_t json_length = ReadU32(glb, 12);
  const uint32_t json_type = ReadU32(glb, 16);
  if (json_type != kChunkJson)
    return InvalidData("GLB chunk 0: type " + Hex(json_type) + ", expected JSON (" + Hex(kChunkJson) + ")");
  const uint64_t json_end = kHeaderBytes + kChunkHeaderBytes + json_length;
  if (json_length == 0 || json_end > glb.size())
    return InvalidData("GLB chunk 0 (JSON): length " + std::to_string(json_length) + " bytes runs past the end of the " +
                       std::to_string(glb.size()) + "-byte file");
  GlbParts parts;
  parts.json = glb.substr(kHeaderBytes + kChunkHeaderBytes, json_length);

  // The BIN chunk is optional; anything shorter than a chunk header after JSON is padding.
  if (glb.size() - json_end >= kChunkHeaderBytes) {
    const uint64_t bin_length = ReadU32(glb, json_end);
    const uint32_t bin_type = ReadU32(glb, json_end + 4);
    if (bin_type != kChunkBin)
      return InvalidData("GLB chunk 1: type " + Hex(bin_type) + ", expected BIN (" + Hex(kChunkBin) + ")");
    if (json_end + kChunkHeaderBytes + bin_length > glb.size())
      return InvalidData("GLB chunk 1 (BIN): length " + std::to_string(bin_length) + " bytes runs past the end of the " +
                         std::to_string(glb.size()) + "-byte file (truncated file?)");
    parts.bin_size_bytes = bin_length;
  }
  return parts;
}

}  // namespace mocapfill::gltf_internal
