#include "formats/file_io.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>

#include "formats/file_reading.h"

namespace mocapfill {

Result<InlineOrFileText> ReadInlineJsonOrFile(const std::string& value, const std::string& option) {
  const size_t first = value.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && value[first] == '{') return InlineOrFileText{value, option};
  ASSIGN_OR_RETURN(std::string text, ReadFileBytes(value));
  return InlineOrFileText{std::move(text), value};
}

Result<std::string> ReadFileBytes(const std::string& path) { return file_reading::ReadWhole<std::string>(path); }

bool IsSameFile(const std::string& a, const std::string& b) {
  struct stat sa {}, sb {};
  if (::stat(a.c_str(), &sa) != 0 || ::stat(b.c_str(), &sb) != 0) return false;
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

std::optional<FileId> IdentifyFile(const std::string& path) {
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) return std::nullopt;
  return FileId{static_cast<uint64_t>(info.st_dev), static_cast<uint64_t>(info.st_ino)};
}

std::string LowerExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

}  // namespace mocapfill
