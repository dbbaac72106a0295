#include "processing/sketch_fill/sketch_keys.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "processing/core/rotation.h"

namespace mocapfill {

namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;

// Key times this close to a frame of the output grid are on it, and two sample times this
// close are one: glTF stores times as float32, whose spacing grows with the time (about
// 4e-6 s at 33 s), so a fixed 1e-6 s would split a 30 Hz key read from a glb from its own frame.
double OnGridS(double time_s) {
  return std::max(1e-6, 4.0 * std::numeric_limits<float>::epsilon() * std::abs(time_s));
}

bool Listed(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool IsAncestorOrSelf(const Skeleton& skeleton, int ancestor, int joint) {
  for (int j = joint; j != kNoParent; j = skeleton.parent(j))
    if (j == ancestor) return true;
  return false;
}

// Linear interpolation of displacements between keys, held outside them.
template <typename T>
T Interpolate(const std::vector<double>& times, const std::vector<T>& values, double t) {
  if (t <= times.front()) return values.front();
  if (t >= times.back()) return values.back();
  const size_t k = static_cast<size_t>(std::upper_bound(times.begin(), times.end(), t) - times.begin());
  const double u = (t - times[k - 1]) / (times[k] - times[k - 1]);
  return ((1.0 - u) * values[k - 1] + u * values[k]).eval();
}

}  // namespace

Status ApplyKeyOverrides(const Skeleton& skeleton, const std::vector<std::string>& keep,
                         const std::vector<std::string>& synthesize, MotionClip& clip) {
  for (const auto* list : {&synthesize, &keep})
    for (const std::string& name : *list)
      RETURN_IF_ERROR(FindJointNamed(skeleton, name, list == &keep ? "keep" : "synthesize").status());
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const std::string& name = skeleton.name(j);
    if (Listed(synthesize, name) || (!keep.empty() && !Listed(keep, name))) clip.keys[j] = JointKeys{};
  }
  return OkStatus();
}

Status CheckTranslationKeys(const Skeleton& skeleton, const MotionClip& clip, int hips,
                            const std::vector<std::string>& position_keys) {
  for (const std::string& name : position_keys) {
    ASSIGN_OR_RETURN(const int joint, FindJointNamed(skeleton, name, "position keys"));
    const std::optional<int> j = joint;
    if (clip.keys[*j].translation_frames.empty())
      return InvalidArgument("position key joint '" + name + "' has no translation keys in the sketch");
  }
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    if (IsAncestorOrSelf(skeleton, j, hips) || Listed(position_keys, skeleton.name(j))) continue;
    double worst = 0.0;
    for (int f : clip.keys[j].translation_frames)
      worst = std::max(worst, (clip.translation(f, j) - skeleton.joint(j).rest_translation).norm());
    if (worst <= 1e-4) continue;
    const double rest = skeleton.joint(j).rest_translation.norm();
    char text[320];
    std::snprintf(text, sizeof text,
                  "joint '%s' has translation keys up to %.1f cm from its rest offset (%.1f cm long): applied as "
                  "bone offsets they would stretch or move the bone; give --position-keys %s to make them "
                  "world-space position targets, or remove them",
                  skeleton.name(j).c_str(), 100.0 * worst, 100.0 * rest, skeleton.name(j).c_str());
    return InvalidData(text);
  }
  return OkStatus();
}

std::vector<double> OutputTimes(const MotionClip& sketch, double rate_hz, bool& uniform) {
  double end = sketch.time_s(sketch.num_frames - 1);
  std::vector<double> keys;
  for (int j = 0; j < sketch.num_joints; ++j) {
    for (double t : RotationKeysOf(sketch, j).times_s) keys.push_back(t);
    for (double t : TranslationKeysOf(sketch, j).times_s) keys.push_back(t);
  }
  for (double t : keys) end = std::max(end, t);
  const int frames = static_cast<int>(std::floor(end * rate_hz + 1e-6)) + 1;
  std::vector<double> times;
  for (int f = 0; f < frames; ++f) times.push_back(f / rate_hz);
  uniform = true;
  for (double t : keys) {
    const double on_grid = std::round(t * rate_hz) / rate_hz;
    if (std::abs(t - on_grid) <= OnGridS(t)) continue;
    times.push_back(t);
    uniform = false;
  }
  std::sort(times.begin(), times.end());
  // Grid frames that fall next to an off-grid key give way to it: the key time is the sample.
  std::vector<double> kept;
  for (double t : times)
    if (kept.empty() || t - kept.back() > OnGridS(t)) kept.push_back(t);
  if (!uniform && kept.back() < end) kept.push_back(end);
  return kept;
}

void PinKeys(const MotionClip& sketch, int hips, MotionClip& out) {
  for (int j = 0; j < sketch.num_joints; ++j) {
    const RotationKeys keys = RotationKeysOf(sketch, j);
    if (!keys.times_s.empty()) {
      std::vector<Vector3d> offsets;
      for (size_t k = 0; k < keys.times_s.size(); ++k) {
        const Quaterniond current = out.rotation(NearestFrame(out, keys.times_s[k]), j);
        offsets.push_back(LogMap(keys.values[k] * current.conjugate()));
      }
      for (int f = 0; f < out.num_frames; ++f) {
        const Vector3d offset = Interpolate(keys.times_s, offsets, out.time_s(f));
        out.rotation(f, j) = (ExpMap(offset) * out.rotation(f, j)).normalized();
      }
      // The displacement is exact where a key sits on a frame; write the key itself there so
      // rounding of the exponential map leaves nothing behind.
      for (size_t k = 0; k < keys.times_s.size(); ++k) out.rotation(NearestFrame(out, keys.times_s[k]), j) = keys.values[k];
    }
    const TranslationKeys moves = TranslationKeysOf(sketch, j);
    if (moves.times_s.empty() || j != hips) continue;
    std::vector<Vector3d> offsets;
    for (size_t k = 0; k < moves.times_s.size(); ++k)
      offsets.push_back(moves.values[k] - out.translation(NearestFrame(out, moves.times_s[k]), j));
    for (int f = 0; f < out.num_frames; ++f) out.translation(f, j) += Interpolate(moves.times_s, offsets, out.time_s(f));
    for (size_t k = 0; k < moves.times_s.size(); ++k)
      out.translation(NearestFrame(out, moves.times_s[k]), j) = moves.values[k];
  }
}

void PinPositionTargets(const Skeleton& skeleton, const std::vector<PositionTarget>& targets, MotionClip& out) {
  std::vector<int> joints;
  for (const PositionTarget& t : targets)
    if (std::find(joints.begin(), joints.end(), t.joint) == joints.end()) joints.push_back(t.joint);
  WorldPose pose;
  for (int joint : joints) {
    std::vector<const PositionTarget*> mine;
    for (const PositionTarget& t : targets)
      if (t.joint == joint) mine.push_back(&t);
    std::sort(mine.begin(), mine.end(), [](const PositionTarget* x, const PositionTarget* y) { return x->time_s < y->time_s; });
    const TwoBoneChain chain = mine.front()->chain;
    const int moved[3] = {chain.upper, chain.lower, chain.end};
    const Vector3d hinge = HingeOf(skeleton, out, chain);
    // The solution at each target time, as offsets from what the fill gave there.
    std::vector<double> times;
    std::vector<TwoBoneSolution> solutions;
    std::vector<std::vector<Vector3d>> offsets(3);
    for (const PositionTarget* t : mine) {
      const int f = NearestFrame(out, t->time_s);
      ComputeWorldPose(skeleton, out, f, pose);
      const TwoBoneSolution s = SolveTwoBoneIk(skeleton, pose, chain, t->position_m, hinge);
      const Quaterniond solved[3] = {s.upper, s.lower, s.end};
      for (int i = 0; i < 3; ++i) offsets[i].push_back(LogMap(solved[i] * out.rotation(f, moved[i]).conjugate()));
      times.push_back(t->time_s);
      solutions.push_back(s);
    }
    for (int f = 0; f < out.num_frames; ++f)
      for (int i = 0; i < 3; ++i)
        out.rotation(f, moved[i]) = (ExpMap(Interpolate(times, offsets[i], out.time_s(f))) * out.rotation(f, moved[i])).normalized();
    for (size_t k = 0; k < times.size(); ++k) {  // the solutions themselves where targets sit on frames
      const int f = NearestFrame(out, times[k]);
      out.rotation(f, chain.upper) = solutions[k].upper;
      out.rotation(f, chain.lower) = solutions[k].lower;
      out.rotation(f, chain.end) = solutions[k].end;
    }
  }
}

std::vector<double> MaxFrameJumpsDeg(const MotionClip& clip) {
  std::vector<double> worst(clip.num_joints, 0.0);
  for (int f = 1; f < clip.num_frames; ++f)
    for (int j = 0; j < clip.num_joints; ++j)
      worst[j] = std::max(worst[j], GeodesicAngle(clip.rotation(f - 1, j), clip.rotation(f, j)) * kDegPerRad);
  return worst;
}

double MaxFrameJumpDeg(const MotionClip& clip) {
  const std::vector<double> jumps = MaxFrameJumpsDeg(clip);
  return jumps.empty() ? 0.0 : *std::max_element(jumps.begin(), jumps.end());
}

}  // namespace mocapfill
