#include "mocapfill/io.h"

#include <optional>

#include "formats/file_io.h"
#include "formats/motion_io.h"
#include "library/api/access.h"

namespace mocapfill::api {

namespace {

ImportOptions ToImport(const LoadOptions& options) {
  ImportOptions out;
  out.unit = options.unit;
  out.up = options.up;
  out.rate_hz = options.rate_hz;
  out.animation = options.animation;
  out.strict = options.strict;
  return out;
}

ExportOptions ToExport(const SaveOptions& options) {
  ExportOptions out;
  out.unit = options.unit;
  out.pretty = options.pretty;
  const std::optional<GltfSkeleton> skeleton = ParseGltfSkeleton(options.gltf_skeleton);
  if (!skeleton)
    ThrowIfError(InvalidArgument("gltf_skeleton: expected skin, mesh or nodes, got '" + options.gltf_skeleton + "'"),
                 FailureStage::kOutput);
  const std::optional<BvhLayout> layout = ParseBvhLayout(options.bvh_layout);
  if (!layout)
    ThrowIfError(InvalidArgument("bvh_layout: expected source or standard, got '" + options.bvh_layout + "'"),
                 FailureStage::kOutput);
  out.gltf_skeleton = *skeleton;
  out.bvh_layout = *layout;
  return out;
}

void CheckOutput(const std::string& path) {
  if (!IsExportExtension(path))
    ThrowIfError(InvalidArgument(path + ": output must end in .gltf, .glb or .bvh"), FailureStage::kOutput);
}

}  // namespace

Scene Load(const std::string& path, const LoadOptions& options) {
  return SceneAccess::Wrap(ValueOrThrow(ImportFile(path, ToImport(options)), FailureStage::kInput));
}

void Save(const Scene& scene, const std::string& path, const SaveOptions& options) {
  CheckOutput(path);
  ThrowIfError(ExportFile(SceneAccess::Get(scene), path, ToExport(options)), FailureStage::kOutput);
}

void Convert(const std::string& input, const std::string& output, const LoadOptions& load, const SaveOptions& save) {
  CheckOutput(output);
  if (IsSameFile(input, output))
    ThrowIfError(IoError(output + ": refusing to overwrite the input"), FailureStage::kOutput);
  const ConvertResult result = ConvertFile(input, output, ToImport(load), ToExport(save));
  ThrowIfError(result.status, result.failed_writing ? FailureStage::kOutput : FailureStage::kInput);
}

}  // namespace mocapfill::api
