// ListMotionFiles (motion_io.h): the motion files a list of files and folders names.
#include <algorithm>
#include <filesystem>

#include "formats/motion_io.h"

namespace fs = std::filesystem;

namespace mocapfill {

Result<std::vector<std::string>> ListMotionFiles(const std::vector<std::string>& paths) {
  std::vector<std::string> files;
  for (const std::string& path : paths) {
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
      for (auto it = fs::recursive_directory_iterator(path, ec); !ec && it != fs::recursive_directory_iterator();
           it.increment(ec))
        if (it->is_regular_file(ec) && IsImportExtension(it->path().string())) files.push_back(it->path().string());
      if (ec) return IoError(path + ": cannot list the folder (" + ec.message() + ")");
    } else if (fs::is_regular_file(path, ec)) {
      files.push_back(path);
    } else {
      return IoError(path + ": no such file or folder");
    }
  }
  std::sort(files.begin(), files.end());
  files.erase(std::unique(files.begin(), files.end()), files.end());
  if (files.empty()) return InvalidArgument("no motion files (.bvh .gltf .glb .fbx) found");
  return files;
}

}  // namespace mocapfill
