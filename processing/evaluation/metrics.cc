#include "processing/evaluation/metrics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "processing/retargeting/rig_mapping.h"

namespace mocapfill {

namespace {

constexpr double kCmPerM = 100.0;
// LaFAN1 contact rule: squared per-frame displacement below 0.02 cm^2 at 30 fps (about 4.2 cm/s).
constexpr double kContactSpeedCmPerS = 4.2426;
constexpr double kSkateThresholdCmPerS = 2.0;
// The fastest a captured foot moves while standing (the database's contact detection, which
// lets heels and toes roll): a filled foot slower than this on a contact frame is sliding.
constexpr double kSlideLimitCmPerS = 30.0;
constexpr double kFloorBandM = 0.01;  // a foot joint this near its floor is on the ground
// The least reference speed of a foot's peak: a walk's feet swing at 2 - 4 m/s, a standing
// capture's shuffle at a fraction of that, which would make any step of the fill a large ratio.
constexpr double kPeakFloorCmPerS = 100.0;

struct Posed {
  std::vector<Eigen::Vector3d> positions;       // [f * J + j], metres
  std::vector<Eigen::Quaterniond> rotations;    // world rotations
};

Posed Pose(const Skeleton& skeleton, const MotionClip& clip) {
  Posed out;
  const size_t n = static_cast<size_t>(clip.num_frames) * clip.num_joints;
  out.positions.resize(n);
  out.rotations.resize(n);
  WorldPose pose;
  for (int f = 0; f < clip.num_frames; ++f) {
    ComputeWorldPose(skeleton, clip, f, pose);
    for (int j = 0; j < clip.num_joints; ++j) {
      out.positions[f * clip.num_joints + j] = pose.positions[j];
      out.rotations[f * clip.num_joints + j] = pose.rotations[j];
    }
  }
  return out;
}

bool InSubtree(const Skeleton& skeleton, int j, int root) {
  for (int p = j; p != kNoParent; p = skeleton.parent(p))
    if (p == root) return true;
  return false;
}

// Names feet by convention: joints whose lower-case name contains "foot", "toe" or "ankle".
bool IsFoot(const std::string& name) {
  std::string lower(name);
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  return lower.find("foot") != std::string::npos || lower.find("toe") != std::string::npos ||
         lower.find("ankle") != std::string::npos;
}

double MeanJerk(const Posed& posed, const std::vector<int>& joints, int frames, int num_joints, double rate) {
  double sum = 0.0;
  long count = 0;
  for (int f = 2; f + 1 < frames; ++f)
    for (int j : joints) {
      auto p = [&](int t) { return posed.positions[t * num_joints + j]; };
      sum += (p(f + 1) - 3.0 * p(f) + 3.0 * p(f - 1) - p(f - 2)).norm() * rate * rate * rate;
      ++count;
    }
  return count ? sum / count : 0.0;
}

void ScoreFeet(const Skeleton& skeleton, const Posed& truth, const Posed& filled, const std::vector<int>& feet,
               int frames, double rate, FillMetrics& m) {
  double sum = 0.0, sliding = 0.0;
  long contacts = 0, skating = 0;
  const int nj = skeleton.num_joints();
  for (int f = 0; f + 1 < frames; ++f)
    for (int j : feet) {
      const double true_speed = (truth.positions[(f + 1) * nj + j] - truth.positions[f * nj + j]).norm() * kCmPerM * rate;
      if (true_speed >= kContactSpeedCmPerS) continue;
      Eigen::Vector3d step = filled.positions[(f + 1) * nj + j] - filled.positions[f * nj + j];
      step.y() = 0.0;
      const double speed = step.norm() * kCmPerM * rate;
      sum += speed;
      if (speed < kSlideLimitCmPerS) sliding += speed;
      ++contacts;
      if (speed > kSkateThresholdCmPerS) ++skating;
    }
  for (int j : feet) {
    double fastest_true = 0.0, fastest_filled = 0.0;
    for (int f = 0; f + 1 < frames; ++f) {
      fastest_true = std::max(fastest_true, (truth.positions[(f + 1) * nj + j] - truth.positions[f * nj + j]).norm());
      fastest_filled =
          std::max(fastest_filled, (filled.positions[(f + 1) * nj + j] - filled.positions[f * nj + j]).norm());
    }
    const double reference = std::max(fastest_true * kCmPerM * rate, kPeakFloorCmPerS);
    m.foot_peak_ratio = std::max(m.foot_peak_ratio, fastest_filled * kCmPerM * rate / reference);
  }
  m.foot_skate_cm_per_s = contacts ? sum / contacts : 0.0;
  m.foot_skate_share = contacts ? double(skating) / contacts : 0.0;
  m.foot_slide_cm_per_s = contacts ? sliding / contacts : 0.0;
  m.foot_contact_frames = contacts;
}

// The foot joints grouped by kind (ankles, toes): one ground per kind, the lowest either side
// reaches in the capture. Each joint's own lowest would take a capture that holds one heel up
// throughout as the ground under that heel, and count a filled foot standing flat as sunk.
// Sides come from the humanoid mapping; a rig it cannot map keeps one group per foot joint.
std::vector<std::vector<int>> FootKinds(const Skeleton& skeleton, const std::vector<int>& feet) {
  std::vector<std::vector<int>> kinds;
  const Result<RigMapping> mapping = MapHumanoid(skeleton, {});
  if (mapping.ok()) {
    for (auto [left, right] : {std::pair{HumanoidBone::kLeftFoot, HumanoidBone::kRightFoot},
                               std::pair{HumanoidBone::kLeftToes, HumanoidBone::kRightToes}}) {
      std::vector<int> kind;
      for (HumanoidBone bone : {left, right})
        if (std::count(feet.begin(), feet.end(), mapping->joint(bone))) kind.push_back(mapping->joint(bone));
      if (!kind.empty()) kinds.push_back(kind);
    }
  }
  auto grouped = [&](int j) {
    return std::any_of(kinds.begin(), kinds.end(),
                       [&](const std::vector<int>& k) { return std::count(k.begin(), k.end(), j); });
  };
  for (int j : feet)
    if (!grouped(j)) kinds.push_back({j});
  return kinds;
}

// Heights are world y (the importers' up axis), as the skating measure's horizontal plane is.
// Per foot joint, the floor of its kind (FootKinds): the truth's lowest height of either side's.
std::vector<std::pair<int, double>> FootFloors(const Skeleton& skeleton, const Posed& truth,
                                               const std::vector<int>& feet, int frames) {
  const int nj = skeleton.num_joints();
  std::vector<std::pair<int, double>> floors;
  for (const std::vector<int>& kind : FootKinds(skeleton, feet)) {
    double ground = std::numeric_limits<double>::infinity();
    for (int j : kind)
      for (int f = 0; f < frames; ++f) ground = std::min(ground, truth.positions[f * nj + j].y());
    for (int j : kind) floors.emplace_back(j, ground);
  }
  return floors;
}

// Mean horizontal speed (cm/s) of `posed`'s foot joints over the steps where both frames are
// within kFloorBandM of their floor; `steps` gets how many there were.
double FloorGlide(const std::vector<std::pair<int, double>>& floors, const Posed& posed, int nj, int frames,
                  double rate, long& steps) {
  double sum = 0.0;
  steps = 0;
  for (const auto& [j, ground] : floors)
    for (int f = 0; f + 1 < frames; ++f) {
      const Eigen::Vector3d& a = posed.positions[f * nj + j];
      const Eigen::Vector3d& b = posed.positions[(f + 1) * nj + j];
      if (a.y() - ground > kFloorBandM || b.y() - ground > kFloorBandM) continue;
      sum += std::hypot(b.x() - a.x(), b.z() - a.z()) * kCmPerM * rate;
      ++steps;
    }
  return steps ? sum / steps : 0.0;
}

void ScorePenetration(const std::vector<std::pair<int, double>>& floors, const Posed& filled, int nj, int frames,
                      FillMetrics& m) {
  double deepest = 0.0, sum = 0.0;
  long below = 0;
  for (const auto& [j, ground] : floors)
    for (int f = 0; f < frames; ++f) {
      const double depth = (ground - filled.positions[f * nj + j].y()) * kCmPerM;
      if (depth <= 0.0) continue;
      deepest = std::max(deepest, depth);
      sum += depth;
      ++below;
    }
  m.penetration_max_cm = deepest;
  m.penetration_mean_cm = below ? sum / below : 0.0;
}

std::vector<std::vector<double>> GlobalQuaternionSignals(const Posed& posed, const std::vector<int>& joints,
                                                         int frames, int num_joints) {
  std::vector<std::vector<double>> dims(joints.size() * 4, std::vector<double>(frames));
  for (size_t i = 0; i < joints.size(); ++i) {
    Eigen::Quaterniond previous = posed.rotations[joints[i]];
    for (int f = 0; f < frames; ++f) {
      Eigen::Quaterniond q = posed.rotations[f * num_joints + joints[i]];
      if (q.dot(previous) < 0) q.coeffs() = -q.coeffs();
      previous = q;
      for (int c = 0; c < 4; ++c) dims[i * 4 + c][f] = q.coeffs()[c];
    }
  }
  return dims;
}

void ScoreKeys(const Skeleton& skeleton, const MotionClip& sketch, const MotionClip& filled, FillMetrics& m) {
  double sum = 0.0, worst = 0.0;
  long count = 0;
  for (int j = 0; j < skeleton.num_joints(); ++j)
    for (int f : sketch.keys[j].rotation_frames) {
      const double e = GeodesicAngle(sketch.rotation(f, j), filled.rotation(f, j)) * kDegPerRad;
      sum += e;
      worst = std::max(worst, e);
      ++count;
    }
  m.key_error_mean_deg = count ? sum / count : 0.0;
  m.key_error_max_deg = worst;
}

double BoneLengthError(const Skeleton& skeleton, const MotionClip& clip, const Posed& truth, const Posed& filled,
                       int frames) {
  const int nj = skeleton.num_joints();
  double sum = 0.0;
  long count = 0;
  for (int j = 0; j < nj; ++j) {
    const int p = skeleton.parent(j);
    if (p == kNoParent || clip.translation_animated[j]) continue;  // root motion is not a bone
    for (int f = 0; f < frames; ++f) {
      const double lt = (truth.positions[f * nj + j] - truth.positions[f * nj + p]).norm();
      if (lt < 1e-9) continue;
      const double lf = (filled.positions[f * nj + j] - filled.positions[f * nj + p]).norm();
      sum += std::abs(lf - lt) / lt;
      ++count;
    }
  }
  return count ? sum / count : 0.0;
}

}  // namespace

const std::vector<MetricField>& AveragedMetricFields() {
  static const std::vector<MetricField> fields = {
      {"mpjpe_unkeyed_cm", &FillMetrics::mpjpe_unkeyed_cm},
      {"mpjpe_keyed_between_cm", &FillMetrics::mpjpe_keyed_between_cm},
      {"angle_unkeyed_deg", &FillMetrics::angle_unkeyed_deg},
      {"npss", &FillMetrics::npss},
      {"jitter_ratio", &FillMetrics::jitter_ratio},
      {"foot_skate_cm_per_s", &FillMetrics::foot_skate_cm_per_s},
      {"foot_skate_share", &FillMetrics::foot_skate_share},
      {"foot_slide_cm_per_s", &FillMetrics::foot_slide_cm_per_s},
      {"penetration_max_cm", &FillMetrics::penetration_max_cm},
      {"penetration_mean_cm", &FillMetrics::penetration_mean_cm},
      {"floor_glide_cm_per_s", &FillMetrics::floor_glide_cm_per_s},
      {"capture_floor_glide_cm_per_s", &FillMetrics::capture_floor_glide_cm_per_s},
      {"foot_peak_ratio", &FillMetrics::foot_peak_ratio},
      {"key_error_mean_deg", &FillMetrics::key_error_mean_deg},
      {"bone_length_error", &FillMetrics::bone_length_error}};
  return fields;
}

double Npss(const std::vector<std::vector<double>>& truth, const std::vector<std::vector<double>>& predicted) {
  double weighted = 0.0, total_power = 0.0;
  for (size_t d = 0; d < truth.size(); ++d) {
    const int n = static_cast<int>(truth[d].size());
    const int bins = n / 2 + 1;
    std::vector<double> pt(bins), pp(bins);
    for (int k = 0; k < bins; ++k) {
      double rt = 0.0, rp = 0.0;
      for (int t = 0; t < n; ++t) {
        const double c = std::cos(2.0 * kPi * k * t / n);
        rt += truth[d][t] * c;
        rp += predicted[d][t] * c;
      }
      pt[k] = rt * rt;
      pp[k] = rp * rp;
    }
    const double st = std::accumulate(pt.begin(), pt.end(), 0.0), sp = std::accumulate(pp.begin(), pp.end(), 0.0);
    if (st <= 0.0 || sp <= 0.0) continue;
    double ct = 0.0, cp = 0.0, emd = 0.0;
    for (int k = 0; k < bins; ++k) {
      ct += pt[k] / st;
      cp += pp[k] / sp;
      emd += std::abs(ct - cp);
    }
    weighted += emd * st;
    total_power += st;
  }
  return total_power > 0.0 ? weighted / total_power : 0.0;
}

Result<FillMetrics> ScoreFill(const Skeleton& skeleton, const MotionClip& truth, const MotionClip& sketch,
                              const MotionClip& filled, int root_joint) {
  const int nj = skeleton.num_joints(), frames = truth.num_frames;
  if (filled.num_frames != frames || sketch.num_frames != frames || filled.num_joints != nj ||
      truth.num_joints != nj || sketch.num_joints != nj)
    return InvalidArgument("ScoreFill: truth, sketch and filled clips differ in frames or joints");
  if (root_joint < 0 || root_joint >= nj) return InvalidArgument("ScoreFill: invalid root joint");
  const Posed pt = Pose(skeleton, truth), pf = Pose(skeleton, filled);
  FillMetrics m;
  double unkeyed_sum = 0.0, keyed_sum = 0.0, angle_sum = 0.0;
  long unkeyed_n = 0, keyed_n = 0;
  std::vector<int> body, feet;
  for (int j = 0; j < nj; ++j) {
    if (j == root_joint || !InSubtree(skeleton, j, root_joint)) continue;
    body.push_back(j);
    if (IsFoot(skeleton.name(j))) feet.push_back(j);
    const std::vector<int>& keys = sketch.keys[j].rotation_frames;
    const bool keyed = !keys.empty();
    if (!keyed) ++m.unkeyed_joints;
    for (int f = 0; f < frames; ++f) {
      const Eigen::Vector3d rt = pt.positions[f * nj + j] - pt.positions[f * nj + root_joint];
      const Eigen::Vector3d rf = pf.positions[f * nj + j] - pf.positions[f * nj + root_joint];
      const double e = (rt - rf).norm() * kCmPerM;
      if (!keyed) {
        unkeyed_sum += e;
        ++unkeyed_n;
        angle_sum += GeodesicAngle(truth.rotation(f, j), filled.rotation(f, j)) * kDegPerRad;
      } else if (!std::binary_search(keys.begin(), keys.end(), f)) {
        keyed_sum += e;
        ++keyed_n;
      }
    }
  }
  m.mpjpe_unkeyed_cm = unkeyed_n ? unkeyed_sum / unkeyed_n : 0.0;
  m.angle_unkeyed_deg = unkeyed_n ? angle_sum / unkeyed_n : 0.0;
  m.mpjpe_keyed_between_cm = keyed_n ? keyed_sum / keyed_n : 0.0;
  m.npss = Npss(GlobalQuaternionSignals(pt, body, frames, nj), GlobalQuaternionSignals(pf, body, frames, nj));
  const double rate = truth.sample_rate_hz;
  const double true_jerk = MeanJerk(pt, body, frames, nj, rate);
  m.jitter_ratio = true_jerk > 0.0 ? MeanJerk(pf, body, frames, nj, rate) / true_jerk : 0.0;
  ScoreFeet(skeleton, pt, pf, feet, frames, rate, m);
  const std::vector<std::pair<int, double>> floors = FootFloors(skeleton, pt, feet, frames);
  ScorePenetration(floors, pf, nj, frames, m);
  m.floor_glide_cm_per_s = FloorGlide(floors, pf, nj, frames, rate, m.floor_steps);
  m.capture_floor_glide_cm_per_s = FloorGlide(floors, pt, nj, frames, rate, m.capture_floor_steps);
  ScoreKeys(skeleton, sketch, filled, m);
  m.bone_length_error = BoneLengthError(skeleton, truth, pt, pf, frames);
  return m;
}

}  // namespace mocapfill
