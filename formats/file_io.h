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
