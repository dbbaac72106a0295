// Whole-file reads and atomic writes. Formats never write to a path directly.
#pragma once

#include <initializer_list>
#include <string>
#include <string_view>

#include "processing/core/status.h"

namespace mocapfill {

// Reads the whole file. Fails with kIoError naming the path.
Result<std::string> ReadFileBytes(const std::string& path);

// Writes `bytes` to a temporary file beside `path`, then renames it over `path`, so a
// crash or error never leaves a partial file. Fails with kIoError naming the path.
Status WriteFileAtomic(const std::string& path, const std::string& bytes);

// WriteFileAtomic of the concatenation of `parts`, without joining them in memory first
// (a .glb's binary chunk is most of the file).
Status WriteFileAtomicParts(const std::string& path, std::initializer_list<std::string_view> parts);

// True when both paths name the same existing file (same device and inode).
bool IsSameFile(const std::string& a, const std::string& b);

// Lower-case extension including the dot (".glb"), or "" when there is none.
std::string LowerExtension(const std::string& path);

}  // namespace mocapfill
