#include "processing/evaluation/sketch_maker.h"

#include <algorithm>

namespace mocapfill {

Status SketchSpec::Validate() const {
  if (keep_joints.empty()) return InvalidArgument("keep_joints: at least one joint must be kept");
  if (key_every_frames < 1)
    return InvalidArgument("key_every_frames: " + std::to_string(key_every_frames) + " must be >= 1");
  return OkStatus();
}

std::vector<int> SketchKeyFrames(int num_frames, int every) {
  std::vector<int> frames;
  for (int f = 0; f < num_frames; f += std::max(1, every)) frames.push_back(f);
  if (num_frames > 0 && frames.back() != num_frames - 1) frames.push_back(num_frames - 1);
  return frames;
}

namespace {

// Interpolates joint j of `clip` between the key frames in place (slerp; lerp translations).
void InterpolateBetweenKeys(MotionClip& clip, int j, const std::vector<int>& keys, bool translation) {
  for (size_t k = 0; k + 1 < keys.size(); ++k) {
    const int a = keys[k], b = keys[k + 1];
    const Eigen::Quaterniond qa = clip.rotation(a, j), qb = clip.rotation(b, j);
    const Eigen::Vector3d ta = clip.translation(a, j), tb = clip.translation(b, j);
    for (int f = a + 1; f < b; ++f) {
      const double u = double(f - a) / (b - a);
      clip.rotation(f, j) = qa.slerp(u, qb).normalized();
      if (translation) clip.translation(f, j) = (1.0 - u) * ta + u * tb;
    }
  }
}

// Whether joint j moves in `clip`: an animated translation, or a rotation that changes.
bool Animated(const MotionClip& clip, int j) {
  if (clip.translation_animated[j]) return true;
  for (int f = 1; f < clip.num_frames; ++f)
    if (clip.rotation(f, j).angularDistance(clip.rotation(0, j)) > 1e-9) return true;
  return false;
}

}  // namespace

Result<MotionClip> MakeSketch(const Skeleton& skeleton, const MotionClip& truth, const SketchSpec& spec) {
  RETURN_IF_ERROR(spec.Validate());
  if (truth.num_frames < 1) return InvalidArgument("clip '" + truth.name + "' has no frames");
  std::vector<bool> keep(skeleton.num_joints(), false);
  for (const std::string& name : spec.keep_joints) {
    const std::optional<int> j = skeleton.Find(name);
    if (!j) return InvalidArgument("keep_joints: joint '" + name + "' is not in the skeleton");
    keep[*j] = true;
  }
  // The topmost kept joints move with their ancestors: where the capture animates a joint above
  // them (a root bone carrying the travel, as some takes of the shared corpus have above their
  // hips), that joint is keyed too, or the sketch would run in place. Joints between two kept
  // ones stay dropped (the arms kept with the hips leave the spine to the fill).
  const std::vector<bool> listed = keep;
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    if (!listed[j]) continue;
    std::vector<int> above;
    int p = skeleton.parent(j);
    for (; p >= 0 && !listed[p]; p = skeleton.parent(p)) above.push_back(p);
    if (p >= 0) continue;  // a kept ancestor carries it
    for (int a : above)
      if (Animated(truth, a)) keep[a] = true;
  }
  MotionClip sketch = MotionClip::RestPose(skeleton, truth.num_frames, truth.sample_rate_hz);
  sketch.name = truth.name + ".sketch";
  const std::vector<int> keys = SketchKeyFrames(truth.num_frames, spec.key_every_frames);
  // Constant translations come from the capture (its offsets may differ from the rest pose).
  for (int f = 0; f < truth.num_frames; ++f)
    for (int j = 0; j < skeleton.num_joints(); ++j)
      if (!truth.translation_animated[j]) sketch.translation(f, j) = truth.translation(f, j);
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    if (!keep[j]) continue;
    const bool moves = truth.translation_animated[j] != 0;
    for (int f : keys) {
      sketch.rotation(f, j) = truth.rotation(f, j);
      if (moves) sketch.translation(f, j) = truth.translation(f, j);
    }
    sketch.translation_animated[j] = truth.translation_animated[j];
    sketch.keys[j].rotation_frames = keys;
    if (moves) sketch.keys[j].translation_frames = keys;
    InterpolateBetweenKeys(sketch, j, keys, moves);
  }
  sketch.MakeContinuous();
  return sketch;
}

}  // namespace mocapfill
