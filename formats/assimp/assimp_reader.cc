#include "formats/assimp/assimp_reader.h"

#include <assimp/Importer.hpp>
#include <assimp/config.h>
#include <assimp/metadata.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <exception>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "formats/assimp/assimp_animation.h"
#include "formats/assimp/assimp_fixups.h"
#include "formats/assimp/assimp_mesh.h"
#include "formats/assimp/assimp_node_graph.h"
#include "formats/file_io.h"
#include "formats/units_axes.h"
#include "processing/core/kinematics.h"

namespace mocapfill {

namespace {

using assimp_detail::ImportedSkeleton;

// Triangles only, shared vertices, at most four weights per vertex, UV origin at the top
// left as in glTF, and Assimp's own consistency checks so a corrupt file fails there, not
// in our code.
// Translation change under which a joint counts as not translating (1 um).
constexpr double kStillTranslationM = 1e-6;

constexpr unsigned kPostProcess = aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
                                  aiProcess_LimitBoneWeights | aiProcess_SortByPType | aiProcess_FlipUVs |
                                  aiProcess_ValidateDataStructure;

Status CheckOptions(const ImportOptions& options) {
  if (options.unit != "auto" && !UnitScaleByName(options.unit))
    return InvalidArgument("unknown unit '" + options.unit + "' (expected auto, m, cm, mm, in, ft or cmu)");
  if (options.up != "auto" && options.up != "y" && options.up != "z")
    return InvalidArgument("unknown up axis '" + options.up + "' (expected auto, y or z)");
  if (!std::isfinite(options.rate_hz) || options.rate_hz < 0.0)
    return InvalidArgument("sample rate must be a positive number of Hz, or 0 to detect it");
  return OkStatus();
}

Result<const aiScene*> ImportScene(Assimp::Importer& importer, const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) return IoError(path + ": is a directory, expected a file");
  if (!std::ifstream(path, std::ios::binary)) return IoError(path + ": cannot open for reading (" + std::strerror(errno) + ")");
  // FBX pivots, offsets and pre/post rotations are kept as $AssimpFbx$ helper nodes, which
  // BuildSkeleton folds into their joint. Assimp 5.2's alternative (PRESERVE_PIVOTS false)
  // bakes the rest transform into one node but still emits the animation as a rotation-only
  // channel for the missing node "<joint>_$AssimpFbx$_Rotation", which cannot be applied
  // without the pivots it dropped (assimp#1068, #4005).
  importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_PRESERVE_PIVOTS, true);
  importer.SetPropertyBool(AI_CONFIG_IMPORT_FBX_READ_TEXTURES, false);
  importer.SetPropertyInteger(AI_CONFIG_PP_LBW_MAX_WEIGHTS, 4);
  const aiScene* scene = nullptr;
  try {  // Assimp reports through its return value; this guards the boundary anyway (bad_alloc)
    scene = importer.ReadFile(path, kPostProcess);
  } catch (const std::exception& e) {
    return InvalidData(path + ": Assimp failed: " + e.what());
  }
  if (scene == nullptr) return InvalidData(path + ": Assimp cannot read it: " + importer.GetErrorString());
  if (scene->mRootNode == nullptr) return InvalidData(path + ": the scene has no nodes");
  return scene;
}

std::optional<double> MetadataNumber(const aiScene& scene, const char* key) {
  const aiMetadata* meta = scene.mMetaData;
  if (meta == nullptr) return std::nullopt;
  for (unsigned i = 0; i < meta->mNumProperties; ++i) {
    if (std::strcmp(meta->mKeys[i].C_Str(), key) != 0 || meta->mValues[i].mData == nullptr) continue;
    const void* data = meta->mValues[i].mData;
    switch (meta->mValues[i].mType) {
      case AI_BOOL: return *static_cast<const bool*>(data) ? 1.0 : 0.0;
      case AI_INT32: return *static_cast<const int32_t*>(data);
      case AI_UINT64: return static_cast<double>(*static_cast<const uint64_t*>(data));
      case AI_FLOAT: return *static_cast<const float*>(data);
      case AI_DOUBLE: return *static_cast<const double*>(data);
      default: return std::nullopt;
    }
  }
  return std::nullopt;
}

Result<std::vector<int>> SelectAnimations(const aiScene& scene, const std::string& wanted) {
  const int count = static_cast<int>(scene.mNumAnimations);
  std::vector<int> all(count);
  for (int a = 0; a < count; ++a) all[a] = a;
  if (wanted.empty()) return all;
  for (int a = 0; a < count; ++a)
    if (wanted == scene.mAnimations[a]->mName.C_Str()) return std::vector<int>{a};
  if (wanted.find_first_not_of("0123456789") == std::string::npos && wanted.size() < 10) {
    const int index = std::stoi(wanted);
    if (index < count) return std::vector<int>{index};
  }
  std::string names;
  for (int a = 0; a < count; ++a)
    names += (a ? ", " : "") + std::to_string(a) + " '" + scene.mAnimations[a]->mName.C_Str() + "'";
  return InvalidArgument("no animation '" + wanted + "'; " +
                         (count ? "the file has " + names : std::string("the file has no animations")));
}

// FBX UnitScaleFactor is centimetres per file unit.
std::string FbxUnitName(double cm_per_unit) {
  const std::pair<const char*, double> known[] = {{"cm", 1.0}, {"m", 100.0}, {"mm", 0.1}, {"in", 2.54}, {"ft", 30.48}};
  for (const auto& [name, cm] : known)
    if (std::abs(cm_per_unit - cm) <= 1e-6 * cm) return name;
  std::ostringstream out;
  out << cm_per_unit << "cm";
  return out.str();
}

// Formats whose unit is the metre by definition (Assimp applies COLLADA's <unit> itself).
bool IsMetreFormat(const std::string& ext) { return ext == ".gltf" || ext == ".glb" || ext == ".dae" || ext == ".ogex"; }

// Unit: --unit, else FBX UnitScaleFactor, else metres for metre formats, else metres
// unless the skeleton's height says otherwise (formats without a declared unit).
Result<UnitChoice> ChooseUnit(const aiScene& ai_scene, const Scene& scene, const ImportOptions& options,
                              const std::string& ext, int up_axis) {
  const std::optional<double> fbx_factor = MetadataNumber(ai_scene, "UnitScaleFactor");
  if (options.unit == "auto" && fbx_factor) {
    if (!(*fbx_factor > 0.0) || !std::isfinite(*fbx_factor))
      return InvalidData("UnitScaleFactor " + std::to_string(*fbx_factor) + " is not a positive number");
    return UnitChoice{FbxUnitName(*fbx_factor), *fbx_factor * 0.01, false};
  }
  if (options.unit == "auto" && IsMetreFormat(ext)) return UnitChoice{"m", 1.0, false};
  return ResolveUnit(options.unit, "m", RestPoseExtent(scene.skeleton, up_axis));
}

// Up axis: --up, else FBX UpAxis/UpAxisSign, else Y. Only Y and Z up are converted.
std::string ChooseUpAxis(const aiScene& ai_scene, const ImportOptions& options, std::vector<std::string>& warnings) {
  if (options.up != "auto") return options.up;
  const std::optional<double> axis = MetadataNumber(ai_scene, "UpAxis");
  if (!axis) return "y";
  const std::optional<double> sign = MetadataNumber(ai_scene, "UpAxisSign");
  const bool negative = sign && *sign < 0.0;
  const char* names[] = {"x", "y", "z"};
  const int a = static_cast<int>(*axis);
  if (a < 0 || a > 2) {
    warnings.push_back("UpAxis " + std::to_string(a) + " is not 0, 1 or 2; assumed Y up");
    return "y";
  }
  const std::string up = std::string(negative ? "-" : "") + names[a];
  if (up != "y" && up != "z") warnings.push_back("up axis " + up + " is not converted (only Y and Z up are)");
  return up;
}

Status ConvertUnitsAndAxes(const aiScene& ai_scene, const ImportOptions& options, const std::string& ext,
                           Scene& scene) {
  const std::string up = ChooseUpAxis(ai_scene, options, scene.warnings);
  ASSIGN_OR_RETURN(const UnitChoice unit, ChooseUnit(ai_scene, scene, options, ext, up == "z" ? 2 : 1));
  if (unit.detected)
    scene.warnings.push_back("unit detected from the skeleton's height: " + unit.name + " (use --unit to override)");
  ScaleScene(scene, unit.scale_to_m);
  if (up == "z") ConvertZUpToYUp(scene);
  scene.source.unit_name = unit.name;
  scene.source.unit_scale_to_m = unit.scale_to_m;
  scene.source.unit_detected = unit.detected;
  scene.source.up_axis = up;
  return OkStatus();
}

// Marks translating joints now that lengths are in metres. As for baked sources,
// translation keys are kept only where the translation moves.
void MarkAnimatedTranslations(Scene& scene) {
  for (MotionClip& clip : scene.clips) {
    clip.DetectAnimatedTranslations(kStillTranslationM);
    for (int j = 0; j < clip.num_joints; ++j)
      if (!clip.translation_animated[j]) {
        clip.keys[j].translation_frames.clear();
        clip.keys[j].translation_times_s.clear();
        clip.keys[j].translation_values.clear();
      }
  }
}

Result<Scene> ConvertScene(const aiScene& ai_scene, const std::string& path, const ImportOptions& options) {
  Scene scene;
  ASSIGN_OR_RETURN(ImportedSkeleton imported, assimp_detail::BuildSkeleton(ai_scene, scene.warnings));
  if (imported.skeleton.num_joints() == 0)
    return Unsupported("no skeleton: no bones, no animated nodes and no transform hierarchy (" +
                       std::to_string(ai_scene.mNumMeshes) + " meshes)");
  scene.skeleton = std::move(imported.skeleton);
  ASSIGN_OR_RETURN(const std::vector<int> selected, SelectAnimations(ai_scene, options.animation));
  for (int a : selected) {
    ASSIGN_OR_RETURN(MotionClip clip, assimp_detail::ConvertAnimation(*ai_scene.mAnimations[a], a, imported.graph,
                                                                      scene.skeleton, options.rate_hz, scene.warnings));
    scene.clips.push_back(std::move(clip));
  }
  RETURN_IF_ERROR(assimp_detail::ConvertMeshes(ai_scene, imported.graph, scene));
  assimp_detail::BakeUniformJointScales(scene);
  const std::string ext = LowerExtension(path);
  RETURN_IF_ERROR(ConvertUnitsAndAxes(ai_scene, options, ext, scene));
  MarkAnimatedTranslations(scene);
  scene.source.format = ext.empty() ? "" : ext.substr(1);
  scene.source.path = path;
  return scene;
}

}  // namespace

Result<Scene> ReadWithAssimp(const std::string& path, const ImportOptions& options) {
  RETURN_IF_ERROR(CheckOptions(options));
  Assimp::Importer importer;
  ASSIGN_OR_RETURN(const aiScene* ai_scene, ImportScene(importer, path));
  Result<Scene> scene = ConvertScene(*ai_scene, path, options);
  if (!scene.ok()) return scene.status().WithContext(path);
  if (options.strict && !scene->warnings.empty())
    return InvalidData(path + ": " + scene->warnings.front() + " (strict mode turns warnings into errors)");
  return scene;
}

}  // namespace mocapfill
