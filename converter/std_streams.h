// "-" as a file argument: standard input spooled into a temporary file (readers take paths,
// and pick the format by extension, which --from gives), and standard output written
// through a temporary file that is copied out only once the whole output exists, so a
// failure writes nothing to the pipe.
#pragma once

#include <string>

#include "processing/core/status.h"

namespace mocapfill::cli {

bool IsStdStream(const std::string& path);  // "-"

// A temporary file (in $TMPDIR or /tmp) removed when this goes away.
class TemporaryFile {
 public:
  // `extension` without the dot ("bvh", "glb").
  static Result<TemporaryFile> Create(const std::string& extension);
  // A file called `name` in a new private folder: for inputs, whose file name becomes the
  // clip's name.
  static Result<TemporaryFile> CreateNamed(const std::string& name);
  TemporaryFile(TemporaryFile&& other) noexcept;
  TemporaryFile& operator=(TemporaryFile&&) = delete;
  TemporaryFile(const TemporaryFile&) = delete;
  ~TemporaryFile();
  const std::string& path() const { return path_; }

 private:
  explicit TemporaryFile(std::string path) : path_(std::move(path)) {}
  std::string path_;
  std::string folder_;  // CreateNamed's folder, removed with the file
};

// Standard input copied into a temporary file "stdin.<extension>". kInvalidArgument when
// the extension is not one ImportFile reads; kIoError when stdin cannot be read or is empty.
Result<TemporaryFile> SpoolStdin(const std::string& extension);

// Copies `path` to standard output. kIoError when the copy fails.
Status CopyToStdout(const std::string& path);

// `message` with every `temporary` path replaced by "-": errors name what the user gave.
std::string AsGiven(std::string message, const std::string& temporary);

}  // namespace mocapfill::cli
