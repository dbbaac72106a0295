#include "formats/bvh/bvh_writer.h"
namespace mocapfill {
Result<std::string> WriteBvh(const Scene&, const ExportOptions&) { return Unsupported("BVH export is not built yet"); }
}  // namespace mocapfill
