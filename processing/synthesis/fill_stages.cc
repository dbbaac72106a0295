#include "processing/synthesis/fill_stages.h"

#include <algorithm>
#include <cmath>

#include "processing/core/monotone_cubic.h"
#include "processing/core/rotation.h"
#include "processing/texturing/repin_keys.h"

namespace mocapfill {

Status CheckFillSketch(const MotionDatabase& db, const MotionClip& sketch) {
  if (sketch.num_frames < 1) return InvalidData("the sketch has no frames");
  RETURN_IF_ERROR(RequireUniform(sketch, "fill"));
  if (std::abs(sketch.sample_rate_hz - db.rate_hz()) > 1e-9 * db.rate_hz())
    return InvalidArgument("the sketch must be resampled to the database rate first");
  return OkStatus();
}

std::vector<std::uint8_t> FixedJoints(const MotionDatabase& db, const SketchSignals& s) {
  std::vector<std::uint8_t> fixed(db.num_joints(), 0);
  for (int j = 0; j < db.num_joints(); ++j) fixed[j] = s.keyed[3 * j];
  for (int p = db.root_joint() >= 0 ? db.skeleton().parent(db.root_joint()) : kNoParent; p != kNoParent;
       p = db.skeleton().parent(p))
    fixed[p] = 1;
  return fixed;
}

namespace {

// The textured root travel (integrated from textured velocities, so it drifts between keys)
// moved onto the sketch's translation keys by a displacement map (repin_keys.h); the height
// (up is +Y, as in the root features) is a smooth curve through the sketch's height keys.
void PinTravelOntoKeys(const MotionClip& sketch, int root, MotionClip& clip) {
  const std::vector<int>& keys = sketch.keys[root].translation_frames;
  Eigen::MatrixXd keyed(clip.num_frames, 3), path(clip.num_frames, 3);
  for (int f = 0; f < clip.num_frames; ++f) {
    keyed.row(f) = sketch.translation(f, root).transpose();
    path.row(f) = clip.translation(f, root).transpose();
  }
  RepinKeys(keyed, {keys, keys, keys}, {0, 2}, path);
  // The height through the same keys without the sketch's kinks, never above or below them:
  // a hip rising past its keys would ask the planted legs for more reach than the keys do.
  std::vector<double> key_heights;
  for (int f : keys) key_heights.push_back(keyed(f, 1));
  const std::vector<double> height = MonotoneCubicThroughKeys(keys, key_heights, clip.num_frames);
  for (int f = 0; f < clip.num_frames; ++f) {
    const bool between_keys = !keys.empty() && f >= keys.front() && f <= keys.back();
    clip.translation(f, root) = Eigen::Vector3d(path(f, 0), between_keys ? height[f] : keyed(f, 1), path(f, 2));
  }
}

}  // namespace

bool RootFeaturesKeyed(const MotionDatabase& db, const SketchSignals& s) {
  return db.root_joint() >= 0 && s.num_channels() > 3 * db.num_joints() && s.keyed[3 * db.num_joints()];
}

Result<MotionClip> ComposeFill(const MotionDatabase& db, const SketchSignals& s, const Eigen::MatrixXd& out,
                               const MotionClip& sketch, bool textured) {
  ClipSignals signals = s.raw;
  signals.tangent = out.leftCols(3 * db.num_joints());
  if (signals.root_features.cols() > 0) signals.root_features = out.rightCols(signals.root_features.cols());
  ASSIGN_OR_RETURN(MotionClip clip, ComposeClip(db.skeleton(), signals, db.reference(), sketch));
  const std::vector<std::uint8_t> fixed = FixedJoints(db, s);
  for (int j = 0; j < db.num_joints(); ++j) {
    const bool copy = (fixed[j] && !(textured && s.keyed[3 * j]));
    const bool root_moves = j == db.root_joint() && RootFeaturesKeyed(db, s);
    const bool pin_travel = root_moves && textured;
    for (int f = 0; f < clip.num_frames; ++f) {
      if (copy) clip.rotation(f, j) = sketch.rotation(f, j);
      if ((copy || root_moves) && !pin_travel) clip.translation(f, j) = sketch.translation(f, j);
    }
    if (pin_travel) PinTravelOntoKeys(sketch, j, clip);
  }
  clip.MakeContinuous();
  clip.KeyAllFrames();
  return clip;
}

void ReportJoints(const MotionDatabase& db, const SketchSignals& s, const MotionClip& sketch, const MotionClip& out,
                  bool textured, FragmentFillReport& report) {
  report.joints.clear();
  report.key_error_max_deg = 0.0;
  double sum = 0.0;
  long count = 0;
  for (int j = 0; j < db.num_joints(); ++j) {
    JointFillInfo info;
    info.name = db.skeleton().name(j);
    info.keys = static_cast<int>(sketch.keys[j].rotation_frames.size());
    info.kind = s.keyed[3 * j] ? (textured ? "textured" : "keyed") : "synthesized";
    for (int f : sketch.keys[j].rotation_frames) {
      const double e = GeodesicAngle(sketch.rotation(f, j), out.rotation(f, j)) * kDegPerRad;
      info.key_error_mean_deg += e;
      info.key_error_max_deg = std::max(info.key_error_max_deg, e);
      sum += e;
      ++count;
    }
    if (info.keys) info.key_error_mean_deg /= info.keys;
    report.key_error_max_deg = std::max(report.key_error_max_deg, info.key_error_max_deg);
    report.joints.push_back(info);
  }
  report.key_error_mean_deg = count ? sum / count : 0.0;
}

}  // namespace mocapfill
