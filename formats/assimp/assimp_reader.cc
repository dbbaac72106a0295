#include "formats/assimp/assimp_reader.h"
namespace mocapfill {
Result<Scene> ReadWithAssimp(const std::string& path, const ImportOptions&) {
  return Unsupported(path + ": Assimp import is not built yet");
}
}  // namespace mocapfill
