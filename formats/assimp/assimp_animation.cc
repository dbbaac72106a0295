#include "formats/assimp/assimp_animation.h"

#include <assimp/anim.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "formats/assimp/assimp_fixups.h"

namespace mocapfill::assimp_detail {

namespace {

constexpr double kDefaultTicksPerSecond = 25.0;  // Assimp's documented default when a file gives none
// Relative deviation from the rest scale above which animated scale is reported as dropped.
constexpr double kScaleDeviation = 1e-4;

// One animated node's keys, in ticks, sorted by time.
struct Track {
  std::vector<double> pos_t, rot_t, scl_t;
  std::vector<Eigen::Vector3d> pos, scl;
  std::vector<Eigen::Quaterniond> rot;
};

Eigen::Vector3d ToVector(const aiVector3D& v) { return {v.x, v.y, v.z}; }
bool IsFinite(const Eigen::Vector3d& v) { return v.allFinite(); }
bool IsFinite(const Eigen::Quaterniond& q) { return q.coeffs().allFinite(); }

// Copies keys sorted by time (Assimp promises order; corrupt files do not keep promises).
template <typename Key, typename Value, typename Convert>
Status CopyKeys(const Key* keys, unsigned count, std::vector<double>& times, std::vector<Value>& values,
                Convert convert, const std::string& what) {
  std::vector<std::pair<double, Value>> pairs;
  pairs.reserve(count);
  for (unsigned k = 0; k < count; ++k) {
    const Value v = convert(keys[k].mValue);
    if (!std::isfinite(keys[k].mTime) || !IsFinite(v))
      return InvalidData(what + ": key " + std::to_string(k) + " is not finite");
    pairs.emplace_back(keys[k].mTime, v);
  }
  std::stable_sort(pairs.begin(), pairs.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [t, v] : pairs) {
    if (!times.empty() && t == times.back()) continue;  // duplicate time: the first key wins
    times.push_back(t);
    values.push_back(v);
  }
  return OkStatus();
}

Result<Track> CopyTrack(const aiNodeAnim& channel, const std::string& what) {
  Track track;
  const auto vec = [](const aiVector3D& v) { return ToVector(v); };
  const auto quat = [](const aiQuaternion& q) { return Eigen::Quaterniond(q.w, q.x, q.y, q.z); };
  RETURN_IF_ERROR(CopyKeys(channel.mPositionKeys, channel.mNumPositionKeys, track.pos_t, track.pos, vec, what + " position"));
  RETURN_IF_ERROR(CopyKeys(channel.mScalingKeys, channel.mNumScalingKeys, track.scl_t, track.scl, vec, what + " scaling"));
  RETURN_IF_ERROR(
      CopyKeys(channel.mRotationKeys, channel.mNumRotationKeys, track.rot_t, track.rot, quat, what + " rotation"));
  for (size_t k = 0; k < track.rot.size(); ++k) {
    if (track.rot[k].norm() < 1e-12) return InvalidData(what + ": rotation key " + std::to_string(k) + " is zero");
    track.rot[k].normalize();
  }
  return track;
}

// Linear interpolation between the keys around `tick`, holding the end keys outside them.
template <typename V, typename Mix>
V SampleKeys(const std::vector<double>& times, const std::vector<V>& values, double tick, Mix mix) {
  if (tick <= times.front()) return values.front();
  if (tick >= times.back()) return values.back();
  const size_t i = std::upper_bound(times.begin(), times.end(), tick) - times.begin();
  const double a = (tick - times[i - 1]) / (times[i] - times[i - 1]);
  return mix(values[i - 1], values[i], a);
}

Eigen::Matrix4d TrackMatrixAt(const Track& track, const Trs& rest, double tick) {
  const auto lerp = [](const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t) -> Eigen::Vector3d {
    return a + (b - a) * t;
  };
  const auto slerp = [](const Eigen::Quaterniond& a, const Eigen::Quaterniond& b, double t) {
    return a.slerp(t, b).normalized();  // Eigen's slerp takes the short arc
  };
  Trs trs = rest;
  if (!track.pos.empty()) trs.translation = SampleKeys(track.pos_t, track.pos, tick, lerp);
  if (!track.rot.empty()) trs.rotation = SampleKeys(track.rot_t, track.rot, tick, slerp);
  if (!track.scl.empty()) trs.scale = SampleKeys(track.scl_t, track.scl, tick, lerp);
  return Compose(trs);
}

void AddKeyFrames(const std::vector<double>& ticks, double shift, double tps, double rate_hz, int frames,
                  std::vector<int>& out) {
  for (double t : ticks) {
    const long f = std::lround((t - shift) / tps * rate_hz);
    out.push_back(static_cast<int>(std::clamp<long>(f, 0, frames - 1)));
  }
}

template <typename T>
void SortUnique(std::vector<T>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

}  // namespace

Result<MotionClip> ConvertAnimation(const aiAnimation& anim, int index, const NodeGraph& g, const Skeleton& skeleton,
                                    double rate_hz, std::vector<std::string>& warnings) {
  const std::string name = anim.mName.length > 0 ? anim.mName.C_Str() : "animation_" + std::to_string(index);
  const std::string what = "animation '" + name + "'";
  double tps = anim.mTicksPerSecond;
  if (!(tps > 0.0) || !std::isfinite(tps)) {
    warnings.push_back(what + " gives no ticks per second; assumed 25");
    tps = kDefaultTicksPerSecond;
  }
  if (anim.mNumMeshChannels > 0 || anim.mNumMorphMeshChannels > 0)
    warnings.push_back(what + ": mesh and morph animation channels are not supported and were dropped");

  // Tracks per node. Channels on nodes outside every joint chain (cameras, lights,
  // skinned-mesh nodes) do not move the skeleton.
  const int num_nodes = static_cast<int>(g.nodes.size());
  std::vector<int> track_of_node(num_nodes, -1);
  std::vector<Track> tracks;
  std::vector<double> all_ticks;
  for (unsigned c = 0; c < anim.mNumChannels; ++c) {
    const aiNodeAnim& channel = *anim.mChannels[c];
    const std::string node_name = channel.mNodeName.C_Str();
    const int v = g.Find(node_name);
    if (v < 0 || !g.in_chain[v]) {
      warnings.push_back(what + ": channel for '" + node_name + "' " +
                         (v < 0 ? "names no node" : "does not move a joint") + "; ignored");
      continue;
    }
    if (track_of_node[v] >= 0) {
      warnings.push_back(what + ": second channel for '" + node_name + "' ignored");
      continue;
    }
    ASSIGN_OR_RETURN(Track track, CopyTrack(channel, what + " channel '" + node_name + "'"));
    for (const auto* times : {&track.pos_t, &track.rot_t, &track.scl_t})
      all_ticks.insert(all_ticks.end(), times->begin(), times->end());
    track_of_node[v] = static_cast<int>(tracks.size());
    tracks.push_back(std::move(track));
  }

  // Timeline: ticks [shift, shift + end_tick] map to seconds [0, end_tick / tps].
  const auto [lo, hi] = std::minmax_element(all_ticks.begin(), all_ticks.end());
  const double first = all_ticks.empty() ? 0.0 : *lo, last = all_ticks.empty() ? 0.0 : *hi;
  const double shift = std::min(0.0, first);
  if (shift < 0.0)
    warnings.push_back(what + " starts at a negative time (" + std::to_string(shift / tps) + " s); shifted to 0");
  const double duration = std::isfinite(anim.mDuration) ? anim.mDuration : 0.0;
  const double end_s = std::max(last - shift, duration) / tps;
  if (rate_hz <= 0.0) {
    std::vector<double> times_s;
    times_s.reserve(all_ticks.size());
    for (double t : all_ticks) times_s.push_back((t - shift) / tps);
    const DetectedRate detected = DetectKeyRateHz(times_s);
    if (!detected.on_grid)
      warnings.push_back(what + ": key times fit no common frame rate; resampled at 30 Hz");
    rate_hz = detected.rate_hz;
  }
  const double frames_d = std::ceil(end_s * rate_hz - 1e-6) + 1.0;
  // The shared bound on frames x joints: a corrupt duration fails cleanly, not out of memory.
  if (!(frames_d * std::max(1, skeleton.num_joints()) <= static_cast<double>(kMaxMotionJointFrames)))
    return InvalidData(what + " lasts " + std::to_string(end_s) + " s, too long to sample at " +
                       std::to_string(rate_hz) + " Hz");
  const int frames = std::max(1, static_cast<int>(frames_d));

  MotionClip clip = MotionClip::RestPose(skeleton, frames, rate_hz);
  clip.name = name;
  std::vector<Trs> node_rest(num_nodes);
  for (int v = 0; v < num_nodes; ++v)
    if (track_of_node[v] >= 0) node_rest[v] = Decompose(g.local[v]);
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const std::vector<int>& chain = g.chains[j];
    if (std::none_of(chain.begin(), chain.end(), [&](int v) { return track_of_node[v] >= 0; })) continue;
    bool scale_dropped = false;
    const Eigen::Vector3d& rest_scale = skeleton.joint(j).rest_scale;
    const auto local_at = [&](double tick) {
      Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
      for (int v : chain)
        local = local * (track_of_node[v] < 0 ? g.local[v] : TrackMatrixAt(tracks[track_of_node[v]], node_rest[v], tick));
      return Decompose(local);
    };
    for (int f = 0; f < frames; ++f) {
      const Trs trs = local_at(shift + clip.time_s(f) * tps);
      clip.rotation(f, j) = trs.rotation;
      clip.translation(f, j) = trs.translation;
      scale_dropped |= (trs.scale - rest_scale).norm() > kScaleDeviation * rest_scale.norm();
    }
    if (scale_dropped)
      warnings.push_back(what + ": scale animation of joint '" + skeleton.name(j) + "' is not supported; rest scale kept");
    // Key ticks of the nodes composing the joint: the exact keys are the composed local
    // transform at each of them.
    std::vector<double> rotation_ticks, translation_ticks;
    for (size_t c = 0; c < chain.size(); ++c) {
      if (track_of_node[chain[c]] < 0) continue;
      const Track& track = tracks[track_of_node[chain[c]]];
      JointKeys& keys = clip.keys[j];
      AddKeyFrames(track.rot_t, shift, tps, rate_hz, frames, keys.rotation_frames);
      AddKeyFrames(track.pos_t, shift, tps, rate_hz, frames, keys.translation_frames);
      rotation_ticks.insert(rotation_ticks.end(), track.rot_t.begin(), track.rot_t.end());
      translation_ticks.insert(translation_ticks.end(), track.pos_t.begin(), track.pos_t.end());
      // A rotation or scale above an offset (an FBX pivot helper) moves the joint's origin.
      const bool offset_below = std::any_of(chain.begin() + c + 1, chain.end(), [&](int v) {
        return g.local[v].block<3, 1>(0, 3).squaredNorm() > 0.0;
      });
      if (offset_below) {
        AddKeyFrames(track.rot_t, shift, tps, rate_hz, frames, keys.translation_frames);
        AddKeyFrames(track.scl_t, shift, tps, rate_hz, frames, keys.translation_frames);
        translation_ticks.insert(translation_ticks.end(), track.rot_t.begin(), track.rot_t.end());
        translation_ticks.insert(translation_ticks.end(), track.scl_t.begin(), track.scl_t.end());
      }
    }
    SortUnique(rotation_ticks);
    SortUnique(translation_ticks);
    JointKeys& keys = clip.keys[j];
    for (double tick : rotation_ticks) {
      keys.rotation_times_s.push_back((tick - shift) / tps);
      keys.rotation_values.push_back(local_at(tick).rotation.normalized());
    }
    for (double tick : translation_ticks) {
      keys.translation_times_s.push_back((tick - shift) / tps);
      keys.translation_values.push_back(local_at(tick).translation);
    }
  }
  for (int j = 0; j < clip.num_joints; ++j) {
    SortUnique(clip.keys[j].rotation_frames);
    SortUnique(clip.keys[j].translation_frames);
  }
  clip.MakeContinuous();
  RETURN_IF_ERROR(clip.Validate(skeleton).WithContext(what));
  return clip;
}

}  // namespace mocapfill::assimp_detail
