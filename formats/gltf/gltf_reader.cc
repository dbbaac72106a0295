// glTF import: container and buffer checks, tinygltf parsing, then the skeleton, meshes
// and animations stages (gltf_*_import.cc), units/axes and provenance.
#include "formats/gltf/gltf_reader.h"

#include "formats/gltf/tinygltf_private.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

#include "formats/file_io.h"
#include "formats/gltf/glb_container.h"
#include "formats/gltf/gltf_buffer_check.h"
#include "formats/gltf/gltf_import_internal.h"
#include "formats/units_axes.h"
#include "processing/core/kinematics.h"

namespace mocapfill {

namespace {

using gltf_internal::AnimationRequest;
using gltf_internal::RecordedClip;

// More keyed frames than a clip may have samples: the extras are damaged, not a clip.
constexpr size_t kMaxRecordedKeys = 20'000'000;

// Extensions whose data our accessor reader handles without special code.
constexpr std::string_view kSupportedRequiredExtensions[] = {"KHR_mesh_quantization"};

// Images are not needed: skip decoding them (and stb_image's work on untrusted bytes).
bool SkipImage(tinygltf::Image*, const int, std::string*, std::string*, int, int, const unsigned char*, int, void*) {
  return true;
}

// tinygltf messages end in newlines and may quote whole data URIs; keep them short.
std::string CleanMessage(const std::string& text) {
  std::string out;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.empty()) continue;
    if (line.size() > 200) line = line.substr(0, 200) + "...";
    out += (out.empty() ? "" : "; ") + line;
  }
  return out;
}

Status CheckOptions(const ImportOptions& options) {
  if (!std::isfinite(options.rate_hz) || options.rate_hz < 0 || options.rate_hz > 10000)
    return InvalidArgument("rate " + std::to_string(options.rate_hz) + " Hz is outside [0, 10000] (0 = detect)");
  if (options.up != "auto" && options.up != "y" && options.up != "z")
    return InvalidArgument("up axis '" + options.up + "' is not auto, y or z");
  return OkStatus();
}

Result<tinygltf::Model> Load(const std::string& bytes, const std::string& path, bool binary,
                             std::vector<std::string>& warnings) {
  std::string base_dir = std::filesystem::path(path).parent_path().string();
  if (base_dir.empty()) base_dir = ".";
  if (bytes.size() > std::numeric_limits<unsigned int>::max()) return Unsupported("files over 4 GB are not supported");
  if (binary) {
    ASSIGN_OR_RETURN(const gltf_internal::GlbParts parts, gltf_internal::ParseGlbContainer(bytes));
    RETURN_IF_ERROR(gltf_internal::CheckJsonSize(parts.json));
    RETURN_IF_ERROR(gltf_internal::CheckBuffers(parts.json, base_dir, parts.bin_size_bytes));
  } else {
    RETURN_IF_ERROR(gltf_internal::CheckJsonSize(bytes));
    RETURN_IF_ERROR(gltf_internal::CheckBuffers(bytes, base_dir, std::nullopt));
  }
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader(&SkipImage, nullptr);
  tinygltf::Model model;
  std::string err, warn;
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  const auto size = static_cast<unsigned int>(bytes.size());
  const bool ok = binary ? loader.LoadBinaryFromMemory(&model, &err, &warn, data, size, base_dir)
                         : loader.LoadASCIIFromString(&model, &err, &warn, bytes.data(), size, base_dir);
  if (!ok) return InvalidData(CleanMessage(err.empty() ? "not a valid glTF file" : err));
  if (!warn.empty()) warnings.push_back("tinygltf: " + CleanMessage(warn));
  for (const std::string& extension : model.extensionsRequired) {
    bool supported = false;
    for (std::string_view s : kSupportedRequiredExtensions) supported = supported || extension == s;
    if (!supported) return Unsupported("extensionsRequired: '" + extension + "' is not supported");
  }
  return model;
}

std::string GetString(const tinygltf::Value& object, const std::string& key) {
  const tinygltf::Value& v = object.Get(key);
  return v.IsString() ? v.Get<std::string>() : std::string();
}

double GetNumber(const tinygltf::Value& object, const std::string& key) {
  const tinygltf::Value& v = object.Get(key);
  return v.IsNumber() ? v.GetNumberAsDouble() : 0.0;
}

// [[first, last], ...] inclusive runs back to a frame list; false when malformed.
bool ReadFrameRanges(const tinygltf::Value& value, std::vector<int>& frames) {
  if (value.Type() == tinygltf::NULL_TYPE) return true;
  if (!value.IsArray()) return false;
  for (size_t k = 0; k < value.ArrayLen(); ++k) {
    const tinygltf::Value& range = value.Get(static_cast<int>(k));
    if (range.ArrayLen() != 2 || !range.Get(0).IsNumber() || !range.Get(1).IsNumber()) return false;
    const int first = range.Get(0).GetNumberAsInt(), last = range.Get(1).GetNumberAsInt();
    if (first < 0 || last < first || frames.size() + (last - first) > kMaxRecordedKeys) return false;
    for (int f = first; f <= last; ++f) frames.push_back(f);
  }
  return true;
}

RecordedClip ReadRecordedClip(const tinygltf::Value& entry) {
  RecordedClip clip;
  clip.name = GetString(entry, "name");
  clip.sample_rate_hz = GetNumber(entry, "sample_rate_hz");
  if (!std::isfinite(clip.sample_rate_hz) || clip.sample_rate_hz < 0 || clip.sample_rate_hz > 10000) clip.sample_rate_hz = 0;
  clip.explicit_frame_times = GetString(entry, "frame_times") == "explicit";
  const tinygltf::Value& keys = entry.Get("keys");
  if (!keys.IsObject()) return clip;
  clip.has_keys = true;
  for (const std::string& joint : keys.Keys()) {
    const tinygltf::Value& k = keys.Get(joint);
    JointKeys joint_keys;
    if (!k.IsObject() || !ReadFrameRanges(k.Get("rotation"), joint_keys.rotation_frames) ||
        !ReadFrameRanges(k.Get("translation"), joint_keys.translation_frames)) {
      clip.has_keys = false;  // malformed: fall back to the keys the channels give
      clip.keys.clear();
      return clip;
    }
    clip.keys[joint] = std::move(joint_keys);
  }
  return clip;
}

// asset.extras.mocapfill as our writer records it: source unit, frame time, clip rates and keys.
void ReadProvenance(const tinygltf::Model& model, SourceInfo& source, AnimationRequest& request) {
  const tinygltf::Value& extras = model.asset.extras;
  if (!extras.IsObject() || !extras.Get("mocapfill").IsObject()) return;
  const tinygltf::Value& info = extras.Get("mocapfill");
  const std::string unit = GetString(info, "unit_name");
  const double metres_per_unit = GetNumber(info, "metres_per_unit");
  if (!unit.empty() && std::isfinite(metres_per_unit) && metres_per_unit > 0) {
    source.unit_name = unit;
    source.unit_scale_to_m = metres_per_unit;
    source.unit_detected = info.Get("unit_detected").IsBool() && info.Get("unit_detected").Get<bool>();
  }
  const std::string up = GetString(info, "source_up_axis");
  if (up == "y" || up == "z") source.up_axis = up;
  source.source_frame_time_text = GetString(info, "source_frame_time_text");
  source.source_frame_time_s = GetNumber(info, "source_frame_time_s");
  const tinygltf::Value& clips = info.Get("clips");
  for (size_t c = 0; c < clips.ArrayLen(); ++c)
    if (clips.Get(static_cast<int>(c)).IsObject()) request.recorded.push_back(ReadRecordedClip(clips.Get(static_cast<int>(c))));
}

Status ApplyUnitsAndAxes(const ImportOptions& options, Scene& scene) {
  if (options.unit != "auto") {
    // A glTF is metres by the spec; an explicit unit says this file was written in another.
    ASSIGN_OR_RETURN(const UnitChoice unit, ResolveUnit(options.unit, "m", RestPoseExtent(scene.skeleton, 1)));
    ScaleScene(scene, unit.scale_to_m);
    scene.source.unit_name = unit.name;
    scene.source.unit_scale_to_m = unit.scale_to_m;
    scene.source.unit_detected = false;
  }
  if (options.up == "z") {
    ConvertZUpToYUp(scene);
    scene.source.up_axis = "z";
  }
  return OkStatus();
}

Result<Scene> Read(const std::string& bytes, const std::string& path, const ImportOptions& options) {
  RETURN_IF_ERROR(CheckOptions(options));
  const bool binary = gltf_internal::HasGlbMagic(bytes) || LowerExtension(path) == ".glb";
  Scene scene;
  ASSIGN_OR_RETURN(const tinygltf::Model model, Load(bytes, path, binary, scene.warnings));
  ASSIGN_OR_RETURN(const gltf_internal::NodeGraph graph, gltf_internal::CheckNodeGraph(model));
  ASSIGN_OR_RETURN(gltf_internal::SkeletonImport skeleton, gltf_internal::ImportSkeleton(model, graph, scene.warnings));
  scene.skeleton = skeleton.skeleton;
  RETURN_IF_ERROR(gltf_internal::ImportMeshes(model, graph, skeleton, scene));

  scene.source.format = binary ? "glb" : "gltf";
  scene.source.path = path;
  AnimationRequest request;
  request.selection = options.animation;
  request.rate_hz = options.rate_hz;
  ReadProvenance(model, scene.source, request);
  ASSIGN_OR_RETURN(scene.clips, gltf_internal::ImportAnimations(model, skeleton, request, scene.warnings));
  RETURN_IF_ERROR(ApplyUnitsAndAxes(options, scene));
  if (options.strict && !scene.warnings.empty())
    return InvalidData(scene.warnings.front() + " (an error under --strict)");
  return scene;
}

}  // namespace

Result<Scene> ReadGltf(const std::string& bytes, const std::string& path, const ImportOptions& options) {
  Result<Scene> scene = Read(bytes, path, options);
  if (!scene.ok()) return scene.status().WithContext(path);
  return scene;
}

}  // namespace mocapfill
