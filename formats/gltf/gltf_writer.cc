#include "formats/gltf/gltf_writer.h"
namespace mocapfill {
Result<std::string> WriteGltf(const Scene&, bool, const ExportOptions&) { return Unsupported("glTF export is not built yet"); }
}  // namespace mocapfill
