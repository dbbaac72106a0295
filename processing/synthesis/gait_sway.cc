#include "processing/synthesis/gait_sway.h"

#include <algorithm>
#include <cmath>

#include "processing/core/rotation.h"
#include "processing/core/signal_layout.h"
#include "processing/filtering/window_mean.h"
#include "processing/motion/tangent_space.h"

namespace mocapfill {

Eigen::VectorXd LateralSway(const Eigen::MatrixXd& root_features, double rate_hz, int half_window) {
  const RootTrajectory path = IntegrateRootFeatures(root_features, rate_hz, 0.0, Eigen::Vector3d::Zero());
  const int frames = static_cast<int>(root_features.rows());
  Eigen::MatrixXd planar(frames, 3);  // x, z and the heading (unwrapped, so it averages without wrapping)
  for (int f = 0; f < frames; ++f)
    planar.row(f) << path.position_m[f].x(), path.position_m[f].z(), path.heading_rad[f];
  const Eigen::MatrixXd centre = WindowMean(planar, half_window);
  Eigen::VectorXd sway(frames);
  for (int f = 0; f < frames; ++f) {
    const Eigen::Vector3d offset(planar(f, 0) - centre(f, 0), 0.0, planar(f, 1) - centre(f, 1));
    sway[f] = offset.dot(YawRotation(centre(f, 2)) * Eigen::Vector3d::UnitX());
  }
  return sway;
}

Eigen::VectorXd DatabaseSway(const MotionDatabase& db, int half_window) {
  Eigen::VectorXd sway = Eigen::VectorXd::Zero(db.num_frames());
  if (db.root_joint() < 0) return sway;
  for (int c = 0; c < db.num_clips(); ++c) {
    const ClipRange& clip = db.clip(c);
    Eigen::MatrixXd features(clip.num_frames, kNumRootFeatures);
    for (int k = 0; k < kNumRootFeatures; ++k)
      features.col(k) = db.ClipRows(db.signals(), c).col(db.RootFeatureChannel(k)).cast<double>();
    sway.segment(clip.first_frame, clip.num_frames) = LateralSway(features, db.rate_hz(), half_window);
  }
  return sway;
}

double SwayAgreement(const Eigen::VectorXd& a, int a_first, int a_last, const Eigen::VectorXd& b, int b_first,
                     int b_last) {
  constexpr int kSamples = 8;
  double dot = 0.0, aa = 0.0, bb = 0.0;
  for (int u = 0; u < kSamples; ++u) {
    const double share = u / static_cast<double>(kSamples - 1);
    const double x = a[a_first + static_cast<int>(std::lround((a_last - a_first) * share))];
    const double y = b[b_first + static_cast<int>(std::lround((b_last - b_first) * share))];
    dot += x * y;
    aa += x * x;
    bb += y * y;
  }
  return aa * bb > 1e-18 ? dot / std::sqrt(aa * bb) : 0.0;
}

void RankBySway(const MatchingDatabase& mdb, const MotionDatabase& db, const std::vector<SketchFragment>& fragments,
                const std::vector<int>& use, const Eigen::VectorXd& sketch_sway, const Eigen::VectorXd& db_sway,
                double weight, std::vector<std::vector<Candidate>>& candidates) {
  for (size_t i = 0; i < candidates.size(); ++i) {
    if (!use[i]) continue;
    const SketchFragment& q = fragments[i];
    for (Candidate& cand : candidates[i]) {
      const DbFragment& g = mdb.fragments()[cand.fragment];
      const int base = db.clip(g.clip).first_frame;
      const double agreement = SwayAgreement(sketch_sway, q.first, q.last, db_sway, base + g.first, base + g.last);
      cand.distance = static_cast<float>(cand.distance * (1.0 + weight * (1.0 - agreement) / 2.0));
    }
    std::stable_sort(candidates[i].begin(), candidates[i].end(),
                     [](const Candidate& x, const Candidate& y) { return x.distance < y.distance; });
  }
}

}  // namespace mocapfill
