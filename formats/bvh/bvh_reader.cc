#include "formats/bvh/bvh_reader.h"
namespace mocapfill {
Result<Scene> ReadBvh(std::string_view, const std::string& path, const ImportOptions&) {
  return Unsupported(path + ": BVH import is not built yet");
}
}  // namespace mocapfill
