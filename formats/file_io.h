// Whole-file reads and atomic writes. Formats never write to a path directly.
#pragma once

#include <compare>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>

#include "formats/atomic_writer.h"  // WriteFileAtomic, WriteFileAtomicParts
#include "formats/file_text.h"
#include "formats/large_buffer.h"
#include "processing/core/status.h"

namespace mocapfill {

// Reads the whole file. Fails with kIoError naming the path.
Result<std::string> ReadFileBytes(const std::string& path);

// An option value that is either inline JSON (its first non-blank character is '{') or the
// path of a file holding it: the text, and what messages about it should name (`option` for
// inline text, else the path). Fails as ReadFileBytes.
struct InlineOrFileText {
  std::string text;
  std::string origin;
};
Result<InlineOrFileText> ReadInlineJsonOrFile(const std::string& value, const std::string& option);
// The same into a LargeBuffer: for motion files, which may be megabytes.
Result<LargeBuffer> ReadFileToBuffer(const std::string& path);

// Regular files of at least this size are mapped by ReadFileText.
inline constexpr size_t kMapFileMinBytes = size_t{1} << 20;
// The same for an input the process leaves mapped until it exits (ImportOptions::
// leave_input_to_exit): no munmap follows, and mapping costs one call where a read costs a
// page fault per 4 KiB of the fresh buffer it fills. A Bandai clip converted from the command
// line took 0.92 of its time mapped (174 clips, paired). Many inputs in one process stay
// at kMapFileMinBytes: there every munmap flushes the other workers' TLBs, and mapping the
// small Bandai clips made a batch 1.48 times slower.
inline constexpr size_t kMapLeftInputMinBytes = size_t{16} << 10;

// The file's bytes for parsing: a regular file of at least `map_min_bytes` mapped
// read-only (file_text.h: check intact() after use), anything else, or a file that cannot
// be mapped, read as ReadFileToBuffer reads it. Fails with kIoError naming the path.
Result<FileText> ReadFileText(const std::string& path, size_t map_min_bytes = kMapFileMinBytes);

// True when both paths name the same existing file (same device and inode).
bool IsSameFile(const std::string& a, const std::string& b);

// Device and inode of an existing file: many paths checked against many others (a batch
// conversion's outputs against its inputs) stat each path once instead of per pair.
struct FileId {
  uint64_t device = 0;
  uint64_t inode = 0;
  friend auto operator<=>(const FileId&, const FileId&) = default;
};
std::optional<FileId> IdentifyFile(const std::string& path);

// Lower-case extension including the dot (".glb"), or "" when there is none.
std::string LowerExtension(const std::string& path);

}  // namespace mocapfill
