#include "formats/file_io.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <type_traits>
#include <utility>

#include "formats/file_descriptor.h"

namespace mocapfill {

namespace {

// Reads from fd at `bytes[filled...]` until `bytes` is full or the file ends; returns
// the bytes now held, or -1 on a read error.
template <class Bytes>
ssize_t ReadInto(int fd, Bytes& bytes, size_t filled) {
  while (filled < bytes.size()) {
    const ssize_t n = ::read(fd, bytes.data() + filled, bytes.size() - filled);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) return -1;
    if (n == 0) break;
    filled += static_cast<size_t>(n);
  }
  return static_cast<ssize_t>(filled);
}

// Opens `path` for reading into `fd` and returns what fstat says of it, or an error
// naming the path.
Result<struct stat> OpenForReading(const std::string& path, FileDescriptor& fd) {
  fd = FileDescriptor(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (fd.get() < 0) {
    const int error = errno;
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return IoError(path + ": is a directory, expected a file");
    return IoError(path + ": cannot open for reading (" + std::strerror(error) + ")");
  }
  struct stat info {};
  if (::fstat(fd.get(), &info) != 0) return IoError(path + ": read failed");
  if (S_ISDIR(info.st_mode)) return IoError(path + ": is a directory, expected a file");
  return info;
}

// The whole open file into `Bytes` (std::string or LargeBuffer), with plain POSIX reads
// into a buffer sized from fstat: a stream-based read copied the file three times and was
// a tenth of a small conversion.
template <class Bytes>
Result<Bytes> ReadOpened(const FileDescriptor& fd, const struct stat& info, const std::string& path) {
  // Regular files are read in one go; pipes and special files (size 0) in chunks. Either
  // way reading goes on to the end, in case the file grew since fstat.
  Bytes bytes;
  size_t filled = 0;
  size_t chunk = S_ISREG(info.st_mode) && info.st_size > 0 ? static_cast<size_t>(info.st_size) + 1 : 65536;
  while (true) {
    if constexpr (std::is_same_v<Bytes, std::string>) {
      bytes.reserve(filled + chunk);
      PrefaultForWrite(bytes.data() + filled, chunk);
    }
    bytes.resize(filled + chunk);
    const ssize_t held = ReadInto(fd.get(), bytes, filled);
    if (held < 0) return IoError(path + ": read failed");
    if (static_cast<size_t>(held) < bytes.size()) {
      bytes.resize(static_cast<size_t>(held));
      return bytes;
    }
    filled = static_cast<size_t>(held);
    chunk = std::max<size_t>(65536, filled);
  }
}

template <class Bytes>
Result<Bytes> ReadWhole(const std::string& path) {
  FileDescriptor fd(-1);
  ASSIGN_OR_RETURN(const struct stat info, OpenForReading(path, fd));
  return ReadOpened<Bytes>(fd, info, path);
}

}  // namespace

Result<InlineOrFileText> ReadInlineJsonOrFile(const std::string& value, const std::string& option) {
  const size_t first = value.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && value[first] == '{') return InlineOrFileText{value, option};
  ASSIGN_OR_RETURN(std::string text, ReadFileBytes(value));
  return InlineOrFileText{std::move(text), value};
}

Result<std::string> ReadFileBytes(const std::string& path) { return ReadWhole<std::string>(path); }

Result<LargeBuffer> ReadFileToBuffer(const std::string& path) { return ReadWhole<LargeBuffer>(path); }

Result<FileText> ReadFileText(const std::string& path, size_t map_min_bytes) {
  FileDescriptor fd(-1);
  ASSIGN_OR_RETURN(const struct stat info, OpenForReading(path, fd));
  if (S_ISREG(info.st_mode) && info.st_size > 0 && static_cast<size_t>(info.st_size) >= map_min_bytes)
    if (std::optional<FileText> text = FileText::Map(fd.get(), static_cast<size_t>(info.st_size)))
      return std::move(*text);
  ASSIGN_OR_RETURN(LargeBuffer bytes, ReadOpened<LargeBuffer>(fd, info, path));
  return FileText(std::move(bytes));
}

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
