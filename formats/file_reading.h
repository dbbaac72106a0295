// Whole-file reading with plain POSIX calls, into any byte container with data(), size()
// and resize(): std::string (file_io.cc) or the fast path's LargeBuffer (fast_convert/).
// Sized from fstat and read in one go, because a stream-based read copies a file three times.
#pragma once

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <system_error>

#include "formats/file_descriptor.h"
#include "processing/core/status.h"

namespace mocapfill::file_reading {

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
inline Result<struct stat> OpenForReading(const std::string& path, FileDescriptor& fd) {
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

// The whole open file. Regular files are read in one go, pipes and special files (size 0)
// in chunks; either way reading goes on to the end, in case the file grew since fstat.
template <class Bytes>
Result<Bytes> ReadOpened(const FileDescriptor& fd, const struct stat& info, const std::string& path) {
  Bytes bytes;
  size_t filled = 0;
  size_t chunk = S_ISREG(info.st_mode) && info.st_size > 0 ? static_cast<size_t>(info.st_size) + 1 : 65536;
  while (true) {
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

}  // namespace mocapfill::file_reading
