// glTF animations to MotionClips: sampler checks, frame-rate choice, resampling onto the
// frame grid, keyed frames and the exact key times and values.
#include "formats/gltf/tinygltf_private.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "formats/gltf/gltf_import_internal.h"
#include "formats/gltf/gltf_keyframes.h"

namespace mocapfill::gltf_internal {

namespace {

// Translations and scales closer than this (m, or scale units) count as equal: float32 data.
constexpr double kValueTolerance = 1e-6;

enum class Path { kTranslation, kRotation, kScale };

struct JointTrack {
  int joint = -1;
  Path path = Path::kRotation;
  KeyTrack track;
};

Result<Interpolation> ParseInterpolation(const std::string& text, const std::string& field) {
  if (text == "LINEAR" || text.empty()) return Interpolation::kLinear;
  if (text == "STEP") return Interpolation::kStep;
  if (text == "CUBICSPLINE") return Interpolation::kCubicSpline;
  return InvalidData(field + ".interpolation: '" + text + "' is not LINEAR, STEP or CUBICSPLINE");
}

Result<std::vector<double>> ReadKeyTimes(const tinygltf::Model& model, int accessor, const std::string& field) {
  Result<AccessorData> input = ReadAccessor(model, accessor);
  if (!input.ok()) return input.status().WithContext(field);
  if (input->components != 1 || input->component_type != TINYGLTF_COMPONENT_TYPE_FLOAT)
    return InvalidData(field + ": accessor " + Str(accessor) + " is not a SCALAR FLOAT accessor of key times");
  const std::vector<double>& t = input->values;
  for (size_t k = 0; k < t.size(); ++k) {
    if (!std::isfinite(t[k])) return InvalidData(field + ": key time at key " + Str(k) + " is not a finite number");
    if (t[k] < 0) return InvalidData(field + ": key time " + std::to_string(t[k]) + " at key " + Str(k) + " is negative");
    if (k > 0 && t[k] <= t[k - 1])
      return InvalidData(field + ": key times are not strictly increasing at key " + Str(k) + " (" +
                         std::to_string(t[k - 1]) + " then " + std::to_string(t[k]) + ")");
  }
  return std::move(input->values);
}

Result<KeyTrack> ReadSampler(const tinygltf::Model& model, const tinygltf::AnimationSampler& sampler,
                             const std::string& field, Path path) {
  KeyTrack track;
  ASSIGN_OR_RETURN(track.interpolation, ParseInterpolation(sampler.interpolation, field));
  ASSIGN_OR_RETURN(track.times_s, ReadKeyTimes(model, sampler.input, field + ".input"));
  Result<AccessorData> output = ReadAccessor(model, sampler.output);
  if (!output.ok()) return output.status().WithContext(field + ".output");
  // Rotations may be stored as normalised integers; everything else must be FLOAT.
  if (output->component_type != TINYGLTF_COMPONENT_TYPE_FLOAT && !(path == Path::kRotation && output->normalized))
    return InvalidData(field + ".output: accessor " + Str(sampler.output) +
                       " must be FLOAT (or normalised integers for rotations)");
  track.components = path == Path::kRotation ? 4 : 3;
  const size_t per_key = track.interpolation == Interpolation::kCubicSpline ? 3 : 1;
  const size_t keys = track.times_s.size();
  if (output->components != track.components || output->count != keys * per_key)
    return InvalidData(field + ".output: accessor " + Str(sampler.output) + " has " + Str(output->count) + " elements of " +
                       Str(output->components) + " components; expected " + Str(keys * per_key) + " of " +
                       Str(track.components) + " for " + Str(keys) + " keys");
  track.values = std::move(output->values);
  for (size_t i = 0; i < track.values.size(); ++i)
    if (!std::isfinite(track.values[i]))
      return InvalidData(field + ".output: non-finite value (NaN or infinity) at key " + Str(i / track.components / per_key));
  if (path == Path::kRotation) {
    for (size_t k = 0; k < keys; ++k) {
      const double* q = &track.values[(k * per_key + (per_key == 3 ? 1 : 0)) * 4];
      if (Eigen::Vector4d(q[0], q[1], q[2], q[3]).norm() < 1e-6)
        return InvalidData(field + ".output: zero-length quaternion at key " + Str(k));
    }
  }
  return track;
}

// Indices of the animations to import: all, or the one named (or numbered) by `selection`.
Result<std::vector<int>> SelectAnimations(const tinygltf::Model& model, const std::string& selection) {
  const int count = static_cast<int>(model.animations.size());
  std::vector<int> all(count);
  for (int a = 0; a < count; ++a) all[a] = a;
  if (selection.empty()) return all;
  // Unnamed animations go by the name their clip gets ("animation_<index>").
  const auto name_of = [&](int a) {
    return model.animations[a].name.empty() ? "animation_" + Str(a) : model.animations[a].name;
  };
  for (int a = 0; a < count; ++a)
    if (name_of(a) == selection) return std::vector<int>{a};
  if (selection.find_first_not_of("0123456789") == std::string::npos && selection.size() < 9) {
    const int index = std::stoi(selection);
    if (index < count) return std::vector<int>{index};
  }
  std::string available;
  for (int a = 0; a < count; ++a)
    available += (a ? ", '" : "'") + name_of(a) + "' (" + Str(a) + ")";
  return InvalidArgument("animation '" + selection + "' not found; " +
                         (count ? "available: " + available : std::string("the file has no animations")));
}

const RecordedClip* FindRecorded(const AnimationRequest& request, const std::string& name) {
  for (const RecordedClip& r : request.recorded)
    if (r.name == name) return &r;
  return nullptr;
}

Result<std::vector<JointTrack>> ReadChannels(const tinygltf::Model& model, const SkeletonImport& skeleton, int a,
                                             std::vector<std::string>& warnings) {
  const tinygltf::Animation& anim = model.animations[a];
  const std::string label = "animations[" + Str(a) + "]";
  if (anim.channels.empty()) return InvalidData(label + ": no channels (an animation needs at least one)");
  std::vector<JointTrack> tracks;
  std::set<std::pair<int, Path>> seen;
  for (size_t c = 0; c < anim.channels.size(); ++c) {
    const tinygltf::AnimationChannel& ch = anim.channels[c];
    const std::string field = label + ".channels[" + Str(c) + "]";
    if (ch.sampler < 0 || static_cast<size_t>(ch.sampler) >= anim.samplers.size())
      return InvalidData(field + ".sampler: sampler " + Str(ch.sampler) + " out of range (" + Str(anim.samplers.size()) + " samplers)");
    Path path;
    if (ch.target_path == "rotation") path = Path::kRotation;
    else if (ch.target_path == "translation") path = Path::kTranslation;
    else if (ch.target_path == "scale") path = Path::kScale;
    else {
      warnings.push_back(field + ": '" + ch.target_path + "' animation ignored (morph weights are not supported)");
      continue;
    }
    const int joint = ch.target_node >= 0 ? skeleton.node_to_joint[ch.target_node] : -1;
    if (joint < 0) {
      warnings.push_back(field + ": target node " + Str(ch.target_node) + " is not a joint of the scene; channel ignored");
      continue;
    }
    if (!seen.insert({joint, path}).second) {
      warnings.push_back(field + ": second " + ch.target_path + " channel of joint '" + skeleton.skeleton.name(joint) + "' ignored");
      continue;
    }
    const std::string sampler_field = label + ".samplers[" + Str(ch.sampler) + "]";
    ASSIGN_OR_RETURN(KeyTrack track, ReadSampler(model, anim.samplers[ch.sampler], sampler_field, path));
    tracks.push_back({joint, path, std::move(track)});
  }
  return tracks;
}

double ChooseRate(const std::vector<JointTrack>& tracks, const AnimationRequest& request, const RecordedClip* recorded,
                  const std::string& label, std::vector<std::string>& warnings) {
  if (request.rate_hz > 0) return request.rate_hz;
  if (recorded && recorded->sample_rate_hz > 0) return recorded->sample_rate_hz;
  std::vector<double> times;
  for (const JointTrack& t : tracks) times.insert(times.end(), t.track.times_s.begin(), t.track.times_s.end());
  if (const auto rate = DetectFrameRate(times)) return *rate;
  warnings.push_back(label + ": key times fit no frame rate of 24-240 Hz; sampled at 30 Hz (choose one with --rate)");
  return 30.0;
}

// A translation channel that never leaves the rest offset is not animation: keep the rest
// value exactly (the clip contract) and leave translation_animated off.
void SettleTranslation(const Skeleton& skeleton, int j, MotionClip& clip) {
  const Eigen::Vector3d rest = skeleton.joint(j).rest_translation;
  bool varies = false;
  for (int f = 0; f < clip.num_frames && !varies; ++f)
    varies = (clip.translation(f, j) - rest).cwiseAbs().maxCoeff() > kValueTolerance;
  clip.translation_animated[j] = varies ? 1 : 0;
  if (!varies)
    for (int f = 0; f < clip.num_frames; ++f) clip.translation(f, j) = rest;
}

// The keys our exporter recorded (asset.extras.mocapfill) for a dense file: key frames index
// the written samples, which are the channels' keys (one per written frame). The exact keys
// are those samples' times and values; the keyed frames are the same indices when the clip
// was uniform (the grid is the recorded rate), else the grid frames nearest those times.
void ApplyRecordedKeys(const RecordedClip& recorded, const Skeleton& skeleton, const std::vector<JointTrack>& tracks,
                       MotionClip& clip, const std::string& label, std::vector<std::string>& warnings) {
  std::vector<const KeyTrack*> rotation(clip.num_joints, nullptr), translation(clip.num_joints, nullptr);
  for (const JointTrack& t : tracks) {
    if (t.path == Path::kRotation) rotation[t.joint] = &t.track;
    if (t.path == Path::kTranslation) translation[t.joint] = &t.track;
  }
  // The written samples' times: every channel of our files shares them.
  const std::vector<double>* written_times = nullptr;
  for (const JointTrack& t : tracks)
    if (t.path != Path::kScale && (!written_times || t.track.times_s.size() > written_times->size()))
      written_times = &t.track.times_s;
  const int written = written_times ? static_cast<int>(written_times->size()) : 0;
  std::vector<JointKeys> keys(clip.num_joints);
  for (const auto& [name, joint_keys] : recorded.keys) {
    const auto j = skeleton.Find(name);
    const auto valid = [&](const std::vector<int>& frames, const KeyTrack* track) {
      const int limit = recorded.explicit_frame_times ? written : clip.num_frames;
      if (track && static_cast<int>(track->times_s.size()) != written) return false;
      for (size_t k = 0; k < frames.size(); ++k)
        if (frames[k] < 0 || frames[k] >= limit || frames[k] >= written || (k && frames[k] <= frames[k - 1]))
          return false;
      return true;
    };
    if (!j || !valid(joint_keys.rotation_frames, rotation[*j]) ||
        !valid(joint_keys.translation_frames, translation[*j])) {
      warnings.push_back(label + ": recorded keys in asset.extras.mocapfill do not match the file; keys taken from the channels");
      return;
    }
    JointKeys& k = keys[*j];
    const std::vector<Eigen::Quaterniond> rotations =
        rotation[*j] ? KeyQuaternions(*rotation[*j]) : std::vector<Eigen::Quaterniond>{};
    const std::vector<Eigen::Vector3d> translations =
        translation[*j] ? KeyVectors(*translation[*j]) : std::vector<Eigen::Vector3d>{};
    for (int f : joint_keys.rotation_frames) {
      k.rotation_times_s.push_back((*written_times)[f]);
      k.rotation_values.push_back(rotation[*j] ? rotations[f] : clip.rotation(0, *j));
    }
    for (int f : joint_keys.translation_frames) {
      k.translation_times_s.push_back((*written_times)[f]);
      k.translation_values.push_back(translation[*j] ? translations[f] : clip.translation(0, *j));
    }
    if (recorded.explicit_frame_times) {
      k.rotation_frames = KeyedFrames({k.rotation_times_s, {}, 4, Interpolation::kLinear}, clip.sample_rate_hz, clip.num_frames);
      k.translation_frames =
          KeyedFrames({k.translation_times_s, {}, 3, Interpolation::kLinear}, clip.sample_rate_hz, clip.num_frames);
    } else {
      k.rotation_frames = joint_keys.rotation_frames;
      k.translation_frames = joint_keys.translation_frames;
    }
  }
  clip.keys = std::move(keys);
}

Result<MotionClip> ImportAnimation(const tinygltf::Model& model, const SkeletonImport& skeleton, int a,
                                   const AnimationRequest& request, std::vector<std::string>& warnings) {
  const std::string label = "animations[" + Str(a) + "]";
  ASSIGN_OR_RETURN(std::vector<JointTrack> tracks, ReadChannels(model, skeleton, a, warnings));
  const Skeleton& skel = skeleton.skeleton;
  MotionClip empty;
  if (tracks.empty()) return empty;  // only morph or foreign channels: nothing for the skeleton

  const std::string& name = model.animations[a].name;
  const RecordedClip* recorded = FindRecorded(request, name);
  const double rate = ChooseRate(tracks, request, recorded, label, warnings);
  double last_s = 0.0;
  for (const JointTrack& t : tracks) last_s = std::max(last_s, t.track.times_s.back());
  const int64_t frames = FrameCount(last_s, rate);
  if (static_cast<double>(frames) * skel.num_joints() > static_cast<double>(kMaxMotionJointFrames))
    return Unsupported(label + ": " + std::to_string(last_s) + " s at " + std::to_string(rate) + " Hz is " + Str(frames) +
                       " frames x " + Str(skel.num_joints()) + " joints, more than the " + Str(kMaxMotionJointFrames) + " samples we accept");

  MotionClip clip = MotionClip::RestPose(skel, static_cast<int>(frames), rate);
  clip.name = name;
  std::vector<char> has_translation(skel.num_joints(), 0);
  for (const JointTrack& t : tracks) {
    if (t.path == Path::kRotation) {
      const auto samples = SampleRotation(t.track, rate, clip.num_frames);
      for (int f = 0; f < clip.num_frames; ++f) clip.rotation(f, t.joint) = samples[f];
      clip.keys[t.joint].rotation_frames = KeyedFrames(t.track, rate, clip.num_frames);
      clip.keys[t.joint].rotation_times_s = t.track.times_s;
      clip.keys[t.joint].rotation_values = KeyQuaternions(t.track);
    } else if (t.path == Path::kTranslation) {
      const auto samples = SampleVector3(t.track, rate, clip.num_frames);
      for (int f = 0; f < clip.num_frames; ++f) clip.translation(f, t.joint) = samples[f];
      clip.keys[t.joint].translation_frames = KeyedFrames(t.track, rate, clip.num_frames);
      clip.keys[t.joint].translation_times_s = t.track.times_s;
      clip.keys[t.joint].translation_values = KeyVectors(t.track);
      has_translation[t.joint] = 1;
    } else {
      const Eigen::Vector3d rest = skel.joint(t.joint).rest_scale;
      for (const Eigen::Vector3d& s : SampleVector3(t.track, rate, clip.num_frames)) {
        if ((s - rest).cwiseAbs().maxCoeff() > kValueTolerance) {
          warnings.push_back(label + ": scale animation of joint '" + skel.name(t.joint) +
                             "' ignored (mocapfill keeps the rest scale)");
          break;
        }
      }
    }
  }
  for (int j = 0; j < skel.num_joints(); ++j)
    if (has_translation[j]) SettleTranslation(skel, j, clip);
  clip.MakeContinuous();
  const bool rate_as_recorded = recorded && (request.rate_hz <= 0 || request.rate_hz == recorded->sample_rate_hz);
  if (rate_as_recorded && recorded->has_keys) ApplyRecordedKeys(*recorded, skel, tracks, clip, label, warnings);
  RETURN_IF_ERROR(clip.Validate(skel).WithContext(label));
  return clip;
}

}  // namespace

Result<std::vector<MotionClip>> ImportAnimations(const tinygltf::Model& model, const SkeletonImport& skeleton,
                                                 const AnimationRequest& request, std::vector<std::string>& warnings) {
  ASSIGN_OR_RETURN(std::vector<int> selected, SelectAnimations(model, request.selection));
  std::vector<MotionClip> clips;
  std::set<std::string> names;
  for (int a : selected) {
    ASSIGN_OR_RETURN(MotionClip clip, ImportAnimation(model, skeleton, a, request, warnings));
    if (clip.num_frames == 0) {
      warnings.push_back("animations[" + Str(a) + "]: no joint animation; skipped");
      continue;
    }
    // Clip names identify clips in reports and selections: make them non-empty and unique.
    const std::string base = clip.name.empty() ? "animation_" + Str(a) : clip.name;
    std::string name = base;
    for (int k = 2; names.count(name); ++k) name = base + "_" + Str(k);
    if (name != clip.name && !clip.name.empty())
      warnings.push_back("animations[" + Str(a) + "]: duplicate name '" + clip.name + "' renamed to '" + name + "'");
    clip.name = name;
    names.insert(name);
    clips.push_back(std::move(clip));
  }
  return clips;
}

}  // namespace mocapfill::gltf_internal
