// Fuzz targets of the JSON the tool reads besides glTF: pipeline files and the two kinds of
// name map.
#include <string>

#include "formats/bvh/bvh_reader.h"
#include "formats/file_io.h"
#include "formats/name_map_json.h"
#include "library/pipeline/file_nodes.h"
#include "library/pipeline/pipeline_file.h"
#include "processing/graph/graph.h"
#include "processing/retargeting/rig_mapping.h"
#include "tests/fuzz/fuzz_targets.h"

namespace mocapfill::fuzz {
namespace {

// The rig a parsed rig map is applied to: the shipped CMU fixture, read once.
const Skeleton* FixtureRig() {
  static const Result<Scene> scene = [] {
    ImportOptions options;
    const std::string path = std::string(MOCAPFILL_FIXTURES_DIR) + "/bvh/cmu_01_01_short.bvh";
    Result<std::string> text = ReadFileBytes(path);
    if (!text.ok()) return Result<Scene>(text.status());
    return ReadBvh(*text, path, options);
  }();
  return scene.ok() ? &scene->skeleton : nullptr;
}

}  // namespace

int FuzzPipeline(const uint8_t* data, size_t size) {
  static const Result<graph::NodeRegistry> registry = MakePipelineRegistry();
  Result<PipelineFile> file = ParsePipelineJson(std::string(reinterpret_cast<const char*>(data), size));
  if (file.ok() && registry.ok()) (void)graph::Graph::Build(file->config, *registry);
  return 0;
}

int FuzzMaps(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  Result<std::map<std::string, std::string>> rig_map = ParseNameMapJson(text, "fuzz.json", kRigMapShape);
  if (rig_map.ok() && FixtureRig() != nullptr) {
    RigMapOptions options;
    options.overrides = *rig_map;
    (void)MapHumanoid(*FixtureRig(), {}, options);
  }
  return 0;
}

}  // namespace mocapfill::fuzz
