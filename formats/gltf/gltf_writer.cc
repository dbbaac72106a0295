// glTF export: joints as nodes, one animation per clip on a shared time accessor, meshes
// and skins, provenance in asset.extras.mocapfill. The model is tinygltf's; .gltf is
// serialised by tinygltf, .glb by tinygltf's JSON serialiser with the binary chunk kept
// apart (GlbFile), so that a large animation is written straight from where it was built.
#include "formats/gltf/gltf_writer.h"

#include "formats/gltf/tinygltf_private.h"

#include <cstdint>
#include <filesystem>
#include <optional>

#include "formats/gltf/gltf_export_internal.h"

namespace mocapfill {

namespace {

using gltf_internal::BufferWriter;
using Value = tinygltf::Value;


Value NumberArray(const Eigen::Vector3d& v) { return Value(Value::Array{Value(v.x()), Value(v.y()), Value(v.z())}); }

void AddJointNodes(const Skeleton& skeleton, tinygltf::Model& model) {
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const Joint& joint = skeleton.joint(j);
    tinygltf::Node node;
    node.name = joint.name;
    if (!joint.rest_translation.isZero(0.0))
      node.translation = {joint.rest_translation.x(), joint.rest_translation.y(), joint.rest_translation.z()};
    const Eigen::Quaterniond r = joint.rest_rotation.normalized();
    if (!r.coeffs().isApprox(Eigen::Quaterniond::Identity().coeffs(), 0.0)) node.rotation = {r.x(), r.y(), r.z(), r.w()};
    if (joint.rest_scale != Eigen::Vector3d::Ones())
      node.scale = {joint.rest_scale.x(), joint.rest_scale.y(), joint.rest_scale.z()};
    for (int c : skeleton.Children(j)) node.children.push_back(c);
    // The BVH layout rides along so that glb -> BVH gives back the source's channels.
    Value::Object extras;
    if (!joint.bvh_channels.empty()) {
      Value::Array channels;
      for (const std::string& c : joint.bvh_channels) channels.emplace_back(c);
      extras["bvh_channels"] = Value(std::move(channels));
    }
    if (joint.end_site) extras["bvh_end_site"] = NumberArray(*joint.end_site);
    if (!extras.empty()) node.extras = Value(std::move(extras));
    model.nodes.push_back(std::move(node));
  }
}

// Unit quaternions as float32 (gltf_tracks.h), kept on one hemisphere from frame to frame;
// joint j's track starts at out + 4 j n. Walked frame by frame, the order the clip stores
// them in.
void WriteRotations(const MotionClip& clip, float* out) {
  const size_t n = clip.num_frames, joints = clip.num_joints;
  std::vector<Eigen::Vector4d> previous(joints, Eigen::Vector4d::Zero());
  for (size_t f = 0; f < n; ++f) PackRotations(&clip.rotations[f * joints], joints, previous.data(), out + 4 * f, 4 * n);
}

// Translations of the `moving` joints as float32; the k-th joint's track starts at out + 3 k n.
void WriteTranslations(const MotionClip& clip, const std::vector<int>& moving, float* out) {
  const size_t n = clip.num_frames;
  for (size_t f = 0; f < n; ++f)
    for (size_t k = 0; k < moving.size(); ++k)
      PackTranslation(clip.translation(static_cast<int>(f), moving[k]), out + 3 * (k * n + f));
}

void AddSampledChannel(tinygltf::Animation& animation, int input, int output, int node, const char* path) {
  tinygltf::AnimationSampler sampler;
  sampler.input = input;
  sampler.output = output;
  sampler.interpolation = "LINEAR";
  animation.samplers.push_back(std::move(sampler));
  tinygltf::AnimationChannel channel;
  channel.sampler = static_cast<int>(animation.samplers.size()) - 1;
  channel.target_node = node;
  channel.target_path = path;
  animation.channels.push_back(std::move(channel));
}

std::vector<int> MovingJoints(const std::vector<std::uint8_t>& translation_animated) {
  std::vector<int> moving;
  for (size_t j = 0; j < translation_animated.size(); ++j)
    if (translation_animated[j]) moving.push_back(static_cast<int>(j));
  return moving;
}

// The buffer views of one clip's tracks (ClipTrackLayout): times, rotations, translations.
struct ClipViews {
  int time = -1;
  int rotation = -1;
  int translation = -1;  // -1 when no joint's translation is animated
};

// The accessors, samplers and channels of one clip over its views: one shared time accessor
// with min/max, a rotation accessor per joint, a translation accessor per moving joint.
void AddAnimationChannels(const std::string& name, const ClipTrackLayout& layout, const std::vector<int>& moving,
                          double first_s, double last_s, const ClipViews& views, BufferWriter& buffer,
                          tinygltf::Model& model) {
  const size_t n = layout.frames;
  const int input =
      buffer.AddAccessor(views.time, 0, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR, n, {first_s}, {last_s});
  tinygltf::Animation animation;
  animation.name = name;
  for (size_t j = 0; j < layout.joints; ++j) {
    const int output = buffer.AddAccessor(views.rotation, j * n * 16, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC4, n);
    AddSampledChannel(animation, input, output, static_cast<int>(j), "rotation");
  }
  for (size_t k = 0; k < moving.size(); ++k) {
    const int output = buffer.AddAccessor(views.translation, k * n * 12, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_VEC3, n);
    AddSampledChannel(animation, input, output, moving[k], "translation");
  }
  model.animations.push_back(std::move(animation));
}

// One shared time accessor, then every joint's rotations, then the animated translations,
// each written straight into the binary buffer.
Status AddAnimation(const MotionClip& clip, BufferWriter& buffer, tinygltf::Model& model) {
  const std::vector<int> moving = MovingJoints(clip.translation_animated);
  const ClipTrackLayout layout{static_cast<size_t>(clip.num_frames), static_cast<size_t>(clip.num_joints), moving.size()};
  const size_t n = layout.frames;
  buffer.Reserve(layout.TotalFloats() * sizeof(float) + 8);

  ClipViews views;
  float* times = buffer.AddFloatView(n, views.time);
  // Uniform clips: frame f at f / rate; others: their explicit sample times.
  if (clip.uniform()) {
    RETURN_IF_ERROR(PackFrameTimes(clip.name, n, clip.sample_rate_hz, times));
  } else {
    RETURN_IF_ERROR(PackExplicitFrameTimes(clip.name, clip.frame_times_s.data(), n, times));
  }
  const double first_s = times[0], last_s = times[n - 1];
  WriteRotations(clip, buffer.AddFloatView(n * 4 * layout.joints, views.rotation));
  if (!moving.empty()) WriteTranslations(clip, moving, buffer.AddFloatView(n * 3 * moving.size(), views.translation));
  AddAnimationChannels(clip.name, layout, moving, first_s, last_s, views, buffer, model);
  return OkStatus();
}

// Inclusive [first, last] runs of a sorted frame list: compact for dense and sparse keys alike.
Value FrameRanges(const std::vector<int>& frames) {
  Value::Array ranges;
  for (size_t k = 0; k < frames.size();) {
    size_t end = k;
    while (end + 1 < frames.size() && frames[end + 1] == frames[end] + 1) ++end;
    ranges.emplace_back(Value::Array{Value(frames[k]), Value(frames[end])});
    k = end + 1;
  }
  return Value(std::move(ranges));
}

// Keys are recorded only when they differ from what re-reading the exported channels gives
// (every frame keyed; translations where animated), i.e. for sparse or partly filled clips.
bool KeysAreDense(const MotionClip& clip) {
  for (int j = 0; j < clip.num_joints; ++j) {
    const JointKeys& k = clip.keys[j];
    if (static_cast<int>(k.rotation_frames.size()) != clip.num_frames) return false;
    const size_t expected_t = clip.translation_animated[j] ? clip.num_frames : 0;
    if (k.translation_frames.size() != expected_t) return false;
  }
  return true;  // sorted, unique and in range (Validate), so the sizes say it all
}

// `sparse_keys`: the clip's keys when they are not dense (KeysAreDense), else nullptr.
Value ClipExtras(const MotionClip& clip, const std::vector<JointKeys>* sparse_keys, const Skeleton& skeleton) {
  Value::Object entry;
  entry["name"] = Value(clip.name);
  entry["sample_rate_hz"] = Value(clip.sample_rate_hz);
  entry["frames"] = Value(clip.num_frames);
  // Explicit sample times live in the time accessor; recorded key frames then index the
  // written samples. Uniform clips record nothing more (their bytes stay as they were).
  if (!clip.uniform()) entry["frame_times"] = Value(std::string("explicit"));
  if (sparse_keys != nullptr) {
    Value::Object keys;
    for (int j = 0; j < clip.num_joints; ++j) {
      const JointKeys& k = (*sparse_keys)[j];
      if (k.empty()) continue;
      Value::Object joint;
      if (!k.rotation_frames.empty()) joint["rotation"] = FrameRanges(k.rotation_frames);
      if (!k.translation_frames.empty()) joint["translation"] = FrameRanges(k.translation_frames);
      keys[skeleton.name(j)] = Value(std::move(joint));
    }
    entry["keys"] = Value(std::move(keys));
  }
  return Value(std::move(entry));
}

// `dense_keys`: every clip is known to be keyed at every frame (its keys are not read).
Value ProvenanceExtras(const Scene& scene, bool dense_keys, const gltf_internal::GeneratedSkeleton* generated) {
  const SourceInfo& s = scene.source;
  Value::Object info;
  info["source_format"] = Value(s.format);
  // The file name only: the full path would make output depend on the machine.
  info["source_file"] = Value(std::filesystem::path(s.path).filename().string());
  info["unit_name"] = Value(s.unit_name);
  info["metres_per_unit"] = Value(s.unit_scale_to_m);
  info["unit_detected"] = Value(s.unit_detected);
  info["source_up_axis"] = Value(s.up_axis);
  info["up_axis_conversion"] = Value(std::string(s.up_axis == "z" ? "z_up_to_y_up" : "none"));
  if (!s.source_frame_time_text.empty()) {
    info["source_frame_time_text"] = Value(s.source_frame_time_text);
    info["source_frame_time_s"] = Value(s.source_frame_time_s);
  }
  Value::Array clips;
  for (const MotionClip& clip : scene.clips)
    clips.push_back(ClipExtras(clip, dense_keys || KeysAreDense(clip) ? nullptr : &clip.keys, scene.skeleton));
  info["clips"] = Value(std::move(clips));
  if (generated != nullptr) {
    Value::Object made;
    made["skin"] = Value(generated->skin);
    if (generated->mesh >= 0) made["mesh"] = Value(generated->mesh);
    info["generated_skeleton"] = Value(std::move(made));
  }
  return Value(Value::Object{{"mocapfill", Value(std::move(info))}});
}

Status CheckExportable(const Scene& scene) {
  if (scene.skeleton.num_joints() == 0) return InvalidArgument("nothing to export: the scene has no skeleton");
  for (const MotionClip& clip : scene.clips) RETURN_IF_ERROR(clip.Validate(scene.skeleton));
  return OkStatus();
}

void AddSceneAndAsset(const Scene& scene, std::vector<int> roots, bool dense_keys,
                      const gltf_internal::GeneratedSkeleton* generated, tinygltf::Model& model) {
  tinygltf::Scene gltf_scene;
  gltf_scene.nodes = std::move(roots);
  model.scenes.push_back(std::move(gltf_scene));
  model.defaultScene = 0;
  model.asset.generator = "mocapfill";
  model.asset.version = "2.0";
  model.asset.extras = ProvenanceExtras(scene, dense_keys, generated);
}

// The skin (and mesh) a scene without a skinned mesh gets, after every other buffer view so
// that a streamed clip's tracks (WriteGlbHeadForTracks) can lead the binary chunk.
Result<std::optional<gltf_internal::GeneratedSkeleton>> AddGeneratedSkeleton(const Scene& scene,
                                                                             const ExportOptions& options,
                                                                             BufferWriter& buffer,
                                                                             tinygltf::Model& model,
                                                                             std::vector<int>& roots) {
  if (!gltf_internal::NeedsGeneratedSkeleton(scene, options.gltf_skeleton))
    return std::optional<gltf_internal::GeneratedSkeleton>();
  ASSIGN_OR_RETURN(const gltf_internal::GeneratedSkeleton generated,
                   gltf_internal::ExportGeneratedSkeleton(scene.skeleton,
                                                          options.gltf_skeleton == GltfSkeleton::kSkinAndMesh, buffer,
                                                          model, roots));
  return std::optional<gltf_internal::GeneratedSkeleton>(generated);
}

void AppendU32(std::string& out, uint32_t v) {
  const char bytes[4] = {static_cast<char>(v), static_cast<char>(v >> 8), static_cast<char>(v >> 16),
                         static_cast<char>(v >> 24)};
  out.append(bytes, 4);
}

// The glb header, the JSON chunk (padded with spaces) and the binary chunk's header,
// exactly as tinygltf's WriteBinaryGltfStream lays them out.
Result<std::string> GlbHead(const std::string& json, size_t bin_bytes) {
  const size_t json_padding = (4 - json.size() % 4) % 4;
  const size_t total = 12 + 8 + json.size() + json_padding + (bin_bytes > 0 ? 8 + bin_bytes : 0);
  if (total > UINT32_MAX) return Unsupported("the .glb would be larger than 4 GiB, the format's limit; write .gltf");
  std::string head;
  head.reserve(28 + json.size() + json_padding);
  head.append("glTF", 4);
  AppendU32(head, 2);
  AppendU32(head, static_cast<uint32_t>(total));
  AppendU32(head, static_cast<uint32_t>(json.size() + json_padding));
  AppendU32(head, 0x4E4F534A);  // "JSON"
  head += json;
  head.append(json_padding, ' ');
  if (bin_bytes > 0) {
    AppendU32(head, static_cast<uint32_t>(bin_bytes));
    AppendU32(head, 0x004E4942);  // "BIN\0"
  }
  return head;
}

}  // namespace

Result<GlbFile> WriteGlb(const Scene& scene, const ExportOptions& options) {
  tinygltf::Model model;
  BufferWriter buffer(model);
  RETURN_IF_ERROR(gltf_internal::BuildExportModel(scene, options, buffer, model));
  GlbFile file;
  file.bin = buffer.TakeBinaryChunk();  // padded to 4 bytes, so the chunk needs no padding
  ASSIGN_OR_RETURN(const std::string json, gltf_internal::GlbJson(model, file.bin.size()));
  ASSIGN_OR_RETURN(file.head, GlbHead(json, file.bin.size()));
  return file;
}

namespace gltf_internal {

Status BuildExportModel(const Scene& scene, const ExportOptions& options, BufferWriter& buffer, tinygltf::Model& model) {
  RETURN_IF_ERROR(CheckExportable(scene));
  AddJointNodes(scene.skeleton, model);
  std::vector<int> roots = scene.skeleton.Roots();
  RETURN_IF_ERROR(ExportMeshes(scene, buffer, model, roots));
  for (const MotionClip& clip : scene.clips) RETURN_IF_ERROR(AddAnimation(clip, buffer, model));
  ASSIGN_OR_RETURN(const auto generated, AddGeneratedSkeleton(scene, options, buffer, model, roots));
  AddSceneAndAsset(scene, std::move(roots), false, generated ? &*generated : nullptr, model);
  return OkStatus();
}

}  // namespace gltf_internal

Result<GlbFile> WriteGlbHeadForTracks(const Scene& scene, const ClipTrackLayout& layout, float first_time_s,
                                      float last_time_s, const ExportOptions& options) {
  if (scene.skeleton.num_joints() == 0) return InvalidArgument("nothing to export: the scene has no skeleton");
  if (scene.clips.size() != 1 || !scene.meshes.empty() || !scene.skins.empty())
    return InvalidArgument("packed tracks describe exactly one clip of a scene without meshes");
  const MotionClip& clip = scene.clips[0];
  const std::vector<int> moving = MovingJoints(clip.translation_animated);
  if (static_cast<size_t>(clip.num_frames) != layout.frames || static_cast<size_t>(clip.num_joints) != layout.joints ||
      static_cast<size_t>(scene.skeleton.num_joints()) != layout.joints || moving.size() != layout.moving ||
      layout.frames == 0)
    return InvalidArgument("packed tracks do not match the clip '" + clip.name + "'");
  tinygltf::Model model;
  BufferWriter buffer(model);
  AddJointNodes(scene.skeleton, model);
  const size_t n = layout.frames;
  ClipViews views;
  views.time = buffer.AddViewAt(0, n * sizeof(float));
  views.rotation = buffer.AddViewAt(layout.RotationTrack(0) * sizeof(float), 4 * n * layout.joints * sizeof(float));
  if (!moving.empty())
    views.translation = buffer.AddViewAt(layout.TranslationTrack(0) * sizeof(float), 3 * n * moving.size() * sizeof(float));
  AddAnimationChannels(clip.name, layout, moving, first_time_s, last_time_s, views, buffer, model);
  const size_t track_bytes = layout.TotalFloats() * sizeof(float);
  buffer.StartAfter(track_bytes);
  std::vector<int> roots = scene.skeleton.Roots();
  ASSIGN_OR_RETURN(const auto generated, AddGeneratedSkeleton(scene, options, buffer, model, roots));
  AddSceneAndAsset(scene, std::move(roots), true, generated ? &*generated : nullptr, model);
  GlbFile file;
  file.bin = buffer.TakeBinaryChunk();
  const size_t bin_bytes = track_bytes + file.bin.size();
  ASSIGN_OR_RETURN(const std::string json, gltf_internal::GlbJson(model, bin_bytes));
  ASSIGN_OR_RETURN(file.head, GlbHead(json, bin_bytes));
  return file;
}

Result<std::string> WriteGltf(const Scene& scene, bool binary, const ExportOptions& options) {
  if (binary) {
    ASSIGN_OR_RETURN(const GlbFile glb, WriteGlb(scene, options));
    std::string bytes;
    bytes.reserve(glb.head.size() + glb.bin.size());
    bytes += glb.head;
    bytes.append(reinterpret_cast<const char*>(glb.bin.data()), glb.bin.size());
    return bytes;
  }
  tinygltf::Model model;
  BufferWriter buffer(model);
  RETURN_IF_ERROR(gltf_internal::BuildExportModel(scene, options, buffer, model));
  buffer.Finish();
  return gltf_internal::GltfJson(model, options.pretty);
}

}  // namespace mocapfill
