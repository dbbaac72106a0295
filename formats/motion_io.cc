#include "formats/motion_io.h"

#include "formats/assimp/assimp_loader.h"
#include "formats/atomic_writer.h"
#include "formats/bvh/bvh_reader.h"
#include "formats/bvh/bvh_writer.h"
#include "formats/fast_convert/fast_convert.h"
#include "formats/file_io.h"
#include "formats/gltf/gltf_reader.h"
#include "formats/gltf/gltf_writer.h"

namespace mocapfill {

namespace {

const char* const kAssimpExtensions[] = {".fbx", ".dae", ".x", ".3ds", ".ms3d", ".md5mesh", ".ogex", ".smd", ".b3d"};

bool IsAssimpExtension(const std::string& ext) {
  for (const char* e : kAssimpExtensions)
    if (ext == e) return true;
  return false;
}

}  // namespace

std::optional<GltfSkeleton> ParseGltfSkeleton(const std::string& name) {
  if (name == "nodes") return GltfSkeleton::kNodes;
  if (name == "skin") return GltfSkeleton::kSkin;
  if (name == "mesh") return GltfSkeleton::kSkinAndMesh;
  return std::nullopt;
}

std::optional<BvhLayout> ParseBvhLayout(const std::string& name) {
  if (name == "source") return BvhLayout::kSource;
  if (name == "standard") return BvhLayout::kStandard;
  return std::nullopt;
}

bool IsAssimpInput(const std::string& path) { return IsAssimpExtension(LowerExtension(path)); }

bool IsImportExtension(const std::string& path) {
  const std::string ext = LowerExtension(path);
  return ext == ".bvh" || ext == ".gltf" || ext == ".glb" || IsAssimpExtension(ext);
}

bool IsExportExtension(const std::string& path) {
  const std::string ext = LowerExtension(path);
  return ext == ".bvh" || ext == ".gltf" || ext == ".glb";
}

Result<Scene> ImportFile(const std::string& path, const ImportOptions& options) {
  const std::string ext = LowerExtension(path);
  if (IsAssimpExtension(ext)) return ReadWithAssimpModule(path, options);
  if (ext != ".bvh" && ext != ".gltf" && ext != ".glb")
    return Unsupported(path + ": unknown input extension '" + ext + "' (expected .bvh, .gltf, .glb or .fbx)");
  ASSIGN_OR_RETURN(std::string bytes, ReadFileBytes(path));
  if (ext == ".bvh") return ReadBvh(bytes, path, options);
  return ReadGltf(bytes, path, options);
}

Status ExportFile(const Scene& scene, const std::string& path, const ExportOptions& options, AtomicWriter* writer) {
  const std::string ext = LowerExtension(path);
  if (ext == ".glb") {
    Result<GlbFile> glb = WriteGlb(scene, options);
    if (!glb.ok()) return glb.status().WithContext(path);
    const std::string_view bin(reinterpret_cast<const char*>(glb->bin.data()), glb->bin.size());
    return WriteFileAtomicParts(path, {glb->head, bin}, writer);
  }
  Result<std::string> bytes = Status();
  if (ext == ".bvh") {
    bytes = WriteBvh(scene, options);
  } else if (ext == ".gltf") {
    bytes = WriteGltf(scene, false, options);
  } else {
    return InvalidArgument(path + ": unknown output extension '" + ext + "' (expected .gltf, .glb or .bvh)");
  }
  if (!bytes.ok()) return bytes.status().WithContext(path);
  return WriteFileAtomicParts(path, {std::string_view(*bytes)}, writer);
}

ConvertResult ConvertFile(const std::string& input, const std::string& output, const ImportOptions& import_options,
                          const ExportOptions& export_options, const ConvertOptions& convert_options,
                          AtomicWriter* writer) {
  const auto export_scene = [&](const Scene& scene) { return ExportFile(scene, output, export_options, writer); };
  if (std::optional<ConvertResult> converted = fast_convert::ConvertBvh(
          input, output, import_options, export_options, convert_options, writer, export_scene))
    return std::move(*converted);
  ConvertResult result;
  Result<Scene> scene = ImportFile(input, import_options);
  if (!scene.ok()) {
    result.status = scene.status();
    return result;
  }
  result.warnings = std::move(scene->warnings);
  result.status = ExportFile(*scene, output, export_options, writer);
  result.failed_writing = !result.status.ok();
  return result;
}

void PrepareConversionProcess() { fast_convert::PrepareProcess(); }

void PrepareBatchConversion() { fast_convert::PrepareBatch(); }

}  // namespace mocapfill
