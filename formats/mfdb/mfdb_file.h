// The .mfdb file: a built MotionDatabase on disk, so fill runs skip the build.
//
// Layout (little-endian): a 64-byte header {magic "MFDB\r\n\x1a\n", u32 version, u32 header
// size, u64 payload size, u64 XXH64 of the payload, reserved zeros}, then the payload: a
// sequence of sections {u32 tag, u32 0, u64 byte length, data, zero padding to 64 bytes}.
// The META section is JSON (skeleton, rate, clips, labels, means, band list); the matrix
// sections are raw float32 column-major arrays, 64-byte aligned. Identical databases give
// identical bytes. Loading reads each section straight into its final buffer while hashing,
// so peak memory is the database itself.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "processing/core/motion_database.h"
#include "processing/core/status.h"

namespace mocapfill {

constexpr std::uint32_t kMfdbVersion = 1;

// The file's bytes. Deterministic.
std::string SerializeMfdb(const MotionDatabase& database);

// Parses bytes produced by SerializeMfdb. Every failure is kInvalidData with a message
// saying what was wrong: "not a mocapfill database (bad magic)", "unsupported version 7
// (this build reads 1)", "truncated: header declares N bytes, file has M", "checksum
// mismatch (file corrupted)", or the inconsistent field.
Result<MotionDatabase> ParseMfdb(std::string_view bytes);

// Writes atomically (WriteFileAtomic). kIoError naming the path on failure.
Status WriteMfdb(const MotionDatabase& database, const std::string& path);

// Reads and verifies a file; errors are prefixed with the path. Unreadable file: kIoError.
Result<MotionDatabase> ReadMfdb(const std::string& path);

// True when the file starts with the .mfdb magic (false when it cannot be read).
bool LooksLikeMfdb(const std::string& path);

}  // namespace mocapfill
