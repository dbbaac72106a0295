#include "converter/std_streams.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "formats/motion_io.h"

namespace mocapfill::cli {

bool IsStdStream(const std::string& path) { return path == "-"; }

namespace {

// "$TMPDIR/mocapfill-XXXXXX" (or under /tmp): the pattern mkstemps and mkdtemp fill in.
std::string TemporaryPattern() {
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/mocapfill-XXXXXX";
}

}  // namespace

Result<TemporaryFile> TemporaryFile::Create(const std::string& extension) {
  const std::string pattern = TemporaryPattern() + "." + extension;
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemps(name.data(), static_cast<int>(extension.size() + 1));
  if (fd < 0) return IoError(pattern + ": cannot create a temporary file (" + std::strerror(errno) + ")");
  ::close(fd);
  return TemporaryFile(std::string(name.data()));
}

Result<TemporaryFile> TemporaryFile::CreateNamed(const std::string& name) {
  const std::string pattern = TemporaryPattern();
  std::vector<char> folder(pattern.begin(), pattern.end());
  folder.push_back('\0');
  if (::mkdtemp(folder.data()) == nullptr)
    return IoError(pattern + ": cannot create a temporary folder (" + std::strerror(errno) + ")");
  TemporaryFile file(std::string(folder.data()) + "/" + name);
  file.folder_ = folder.data();
  return file;
}

TemporaryFile::TemporaryFile(TemporaryFile&& other) noexcept
    : path_(std::move(other.path_)), folder_(std::move(other.folder_)) {
  other.path_.clear();
  other.folder_.clear();
}

TemporaryFile::~TemporaryFile() {
  if (!path_.empty()) ::unlink(path_.c_str());
  if (!folder_.empty()) ::rmdir(folder_.c_str());
}

Result<TemporaryFile> SpoolStdin(const std::string& extension) {
  if (extension.empty() || !IsImportExtension("stdin." + extension))
    return InvalidArgument("-: reading standard input needs --from with the input's format (bvh, gltf, glb, fbx), got '" +
                           extension + "'");
  ASSIGN_OR_RETURN(TemporaryFile file, TemporaryFile::CreateNamed("stdin." + extension));
  std::FILE* out = std::fopen(file.path().c_str(), "wb");
  if (out == nullptr) return IoError(file.path() + ": cannot write (" + std::strerror(errno) + ")");
  std::vector<char> buffer(1 << 16);
  size_t total = 0;
  for (size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), stdin)) > 0; total += n)
    if (std::fwrite(buffer.data(), 1, n, out) != n) {
      std::fclose(out);
      return IoError(file.path() + ": cannot write (" + std::strerror(errno) + ")");
    }
  const bool read_failed = std::ferror(stdin) != 0;
  if (std::fclose(out) != 0) return IoError(file.path() + ": cannot write (" + std::strerror(errno) + ")");
  if (read_failed) return IoError("-: cannot read standard input");
  if (total == 0) return InvalidData("-: standard input is empty");
  return file;
}

Status CopyToStdout(const std::string& path) {
  std::FILE* in = std::fopen(path.c_str(), "rb");
  if (in == nullptr) return IoError(path + ": cannot read (" + std::strerror(errno) + ")");
  std::vector<char> buffer(1 << 16);
  for (size_t n; (n = std::fread(buffer.data(), 1, buffer.size(), in)) > 0;)
    if (std::fwrite(buffer.data(), 1, n, stdout) != n) {
      std::fclose(in);
      return IoError("-: cannot write standard output");
    }
  std::fclose(in);
  if (std::fflush(stdout) != 0) return IoError("-: cannot write standard output");
  return OkStatus();
}

std::string AsGiven(std::string message, const std::string& temporary) {
  if (temporary.empty()) return message;
  for (size_t at; (at = message.find(temporary)) != std::string::npos;) message.replace(at, temporary.size(), "-");
  return message;
}

}  // namespace mocapfill::cli
