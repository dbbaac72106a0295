#include "formats/gltf/gltf_reader.h"
namespace mocapfill {
Result<Scene> ReadGltf(const std::string&, const std::string& path, const ImportOptions&) {
  return Unsupported(path + ": glTF import is not built yet");
}
}  // namespace mocapfill
