#include "formats/bvh/bvh_reader.h"

#include <algorithm>
#include <filesystem>
#include <utility>
#include <vector>

#include "formats/bvh/bvh_hierarchy.h"
#include "formats/bvh/bvh_lexer.h"
#include "formats/bvh/bvh_motion.h"
#include "formats/bvh/bvh_scene.h"
#include "formats/units_axes.h"
#include "processing/core/kinematics.h"

namespace mocapfill {

namespace bvh {

namespace {

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";
// A rest pose whose extent along the up axis is below this share of its widest extent does
// not stand (see ResolveBvhUnit).
constexpr double kFlatRestPoseShare = 0.25;

}  // namespace

Status CheckImportOptions(const ImportOptions& options) {
  if (options.up != "auto" && options.up != "y" && options.up != "z")
    return InvalidArgument("unknown up axis '" + options.up + "' (expected auto, y or z)");
  if (options.unit != "auto" && !UnitScaleByName(options.unit))
    return InvalidArgument("unknown unit '" + options.unit + "' (expected auto, m, cm, mm, in, ft or cmu)");
  return OkStatus();
}

std::string_view WithoutByteOrderMark(std::string_view text) {
  if (text.substr(0, kUtf8Bom.size()) == kUtf8Bom) text.remove_prefix(kUtf8Bom.size());
  return text;
}

Result<Skeleton> BuildSkeleton(const ParsedHierarchy& hierarchy, const std::string& path) {
  std::vector<Joint> joints;
  joints.reserve(hierarchy.joints.size());
  for (const ParsedJoint& parsed : hierarchy.joints) {
    Joint joint;
    joint.name = parsed.name;
    joint.parent = parsed.parent;
    joint.rest_translation = parsed.offset;
    for (Channel c : parsed.layout.channels) joint.bvh_channels.emplace_back(ChannelName(c));
    joint.end_site = parsed.end_site;
    joints.push_back(std::move(joint));
  }
  Result<Skeleton> skeleton = Skeleton::Build(std::move(joints));
  if (!skeleton.ok()) return skeleton.status().WithContext(path);
  return skeleton;
}

Status CheckFrameCount(const MotionHeader& header, int rows, const std::string& path, bool strict,
                       std::vector<std::string>& warnings) {
  const std::string where = path + ":" + std::to_string(header.frames_location.line) + ":" +
                            std::to_string(header.frames_location.column) + ": ";
  if (rows == 0)
    return InvalidData(where + "the motion section holds no frames (Frames: " + std::to_string(header.declared_frames) +
                       ")");
  if (rows == header.declared_frames) return OkStatus();
  const std::string message = "Frames declares " + std::to_string(header.declared_frames) +
                              " frames but the file holds " + std::to_string(rows) + " rows";
  if (strict) return InvalidData(where + message);
  warnings.push_back(where + message + "; using the " + std::to_string(rows) + " rows present");
  return OkStatus();
}

Result<UnitChoice> ResolveBvhUnit(const Skeleton& skeleton, const ImportOptions& options) {
  double height = RestPoseExtent(skeleton, options.up == "z" ? 2 : 1);
  // A rest pose that does not stand says little about the height: Bandai-Namco's bones run
  // along +X, and only the hips' OFFSET lifts them; written in the standard layout (hips
  // OFFSET zero, their height in the position channels) the pose lies flat. Its widest
  // extent then stands in for the height.
  double widest = 0.0;
  for (int axis = 0; axis < 3; ++axis) widest = std::max(widest, RestPoseExtent(skeleton, axis));
  if (height < kFlatRestPoseShare * widest) height = widest;
  return ResolveUnit(options.unit, "cm", height);
}

SourceInfo BvhSource(const std::string& path, const MotionHeader& header, const UnitChoice& unit, bool z_up) {
  SourceInfo source;
  source.format = "bvh";
  source.path = path;
  source.source_frame_time_s = header.frame_time_s;
  source.source_frame_time_text = header.frame_time_text;
  source.declared_frames = static_cast<int>(header.declared_frames);
  source.unit_name = unit.name;
  source.unit_scale_to_m = unit.scale_to_m;
  source.unit_detected = unit.detected;
  source.up_axis.assign(1, z_up ? 'z' : 'y');  // (char form: gcc 12 -Wrestrict false positive)
  return source;
}

std::string ClipName(const std::string& path) {
  const std::string stem = std::filesystem::path(path).stem().string();
  return stem.empty() ? std::string("bvh") : stem;
}

bool HasPositionChannels(const Joint& joint) {
  for (const std::string& channel : joint.bvh_channels)
    if (channel.find("position") != std::string::npos) return true;
  return false;
}

void AdoptConstantPosition(Joint& joint, const Eigen::Vector3d& used) {
  if (used == joint.rest_translation) return;
  joint.bvh_offset = joint.rest_translation;
  joint.rest_translation = used;
}

}  // namespace bvh

namespace {

// MotionClip::DetectAnimatedTranslations' test (a frame off frame 0 by more than its
// default tolerance), run only on joints with position channels: the others hold their
// OFFSET exactly, and skipping them saves a strided pass over the whole clip.
bool TranslationMoves(const MotionClip& clip, int joint) {
  constexpr double kAnimatedToleranceM = 1e-9;
  const Eigen::Vector3d& first = clip.translation(0, joint);
  for (int f = 1; f < clip.num_frames; ++f)
    if ((clip.translation(f, joint) - first).cwiseAbs().maxCoeff() > kAnimatedToleranceM) return true;
  return false;
}

// Joints whose position channels hold one value over the whole clip are not animated
// (bvh::AdoptConstantPosition); every frame then holds exactly the rest value.
void AdoptConstantPositions(Scene& scene) {
  MotionClip& clip = scene.clips[0];
  clip.translation_animated.assign(clip.num_joints, 0);
  for (int j = 0; j < clip.num_joints; ++j) {
    Joint& joint = scene.skeleton.mutable_joint(j);
    if (!bvh::HasPositionChannels(joint)) continue;
    clip.translation_animated[j] = TranslationMoves(clip, j);
    if (clip.translation_animated[j]) continue;
    const Eigen::Vector3d used = clip.translation(0, j);
    if (used == joint.rest_translation) continue;
    bvh::AdoptConstantPosition(joint, used);
    for (int f = 0; f < clip.num_frames; ++f) clip.translation(f, j) = used;
  }
}

}  // namespace

Result<Scene> ReadBvh(std::string_view text, const std::string& path, const ImportOptions& options,
                      MotionRowsParser parse_rows) {
  RETURN_IF_ERROR(bvh::CheckImportOptions(options));
  bvh::BvhLexer lexer(bvh::WithoutByteOrderMark(text), path);
  ASSIGN_OR_RETURN(bvh::ParsedHierarchy hierarchy, bvh::ParseHierarchy(lexer));
  ASSIGN_OR_RETURN(const bvh::MotionHeader header, bvh::ParseMotionHeader(lexer));
  if (hierarchy.num_channels == 0)
    return lexer.ErrorAt(header.frames_location, "the hierarchy declares no channels, so there is no motion to read");

  Scene scene;
  scene.warnings = std::move(hierarchy.warnings);
  MotionClip clip;
  clip.name = bvh::ClipName(path);
  clip.sample_rate_hz = bvh::SnapFrameRate(header.frame_time_s);
  RETURN_IF_ERROR(bvh::ParseMotionRows(lexer, hierarchy, header, clip, parse_rows));
  RETURN_IF_ERROR(bvh::CheckFrameCount(header, clip.num_frames, path, options.strict, scene.warnings));
  ASSIGN_OR_RETURN(scene.skeleton, bvh::BuildSkeleton(hierarchy, path));
  scene.clips.push_back(std::move(clip));

  const bool z_up = options.up == "z";
  ASSIGN_OR_RETURN(const UnitChoice unit, bvh::ResolveBvhUnit(scene.skeleton, options));
  scene.source = bvh::BvhSource(path, header, unit, z_up);
  ScaleScene(scene, unit.scale_to_m);
  AdoptConstantPositions(scene);
  if (z_up) ConvertZUpToYUp(scene);
  // Finite values, unit and hemisphere-continuous quaternions hold by construction, so
  // neither Validate() nor MakeContinuous() passes are needed here.
  scene.clips[0].KeyAllFrames();
  return scene;
}

}  // namespace mocapfill
