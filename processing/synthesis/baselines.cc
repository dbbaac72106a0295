#include "processing/synthesis/baselines.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace mocapfill {

void FillMean(const SketchSignals& sketch, Eigen::MatrixXd& out) {
  for (int c = 0; c < sketch.num_channels(); ++c)
    if (!sketch.keyed[c]) out.col(c).setZero();
}

Eigen::VectorXf ChannelSigma(const MotionDatabase& db) {
  const Eigen::MatrixXf& s = db.signals();
  const Eigen::RowVectorXf mean = s.colwise().mean();
  Eigen::VectorXf sigma = ((s.rowwise() - mean).array().square().colwise().mean()).sqrt().transpose();
  return sigma.cwiseMax(1e-6f);
}

std::vector<int> FillNearest(const MotionDatabase& db, const SketchSignals& sketch, const FragmentFillOptions& options,
                             Eigen::MatrixXd& out) {
  std::vector<int> keyed, unkeyed;
  for (int c = 0; c < sketch.num_channels(); ++c) (sketch.keyed[c] ? keyed : unkeyed).push_back(c);
  const Eigen::VectorXf sigma = ChannelSigma(db);
  const std::vector<int>& keys = sketch.all_key_frames;
  Eigen::MatrixXf queries(keys.size(), keyed.size());
  Eigen::MatrixXf database(db.num_frames(), keyed.size());
  for (size_t i = 0; i < keyed.size(); ++i) {
    const int c = keyed[i];
    const bool root = c >= 3 * db.num_joints();
    const float scale = (root ? static_cast<float>(std::sqrt(options.root_feature_weight)) : 1.0f) / sigma[c];
    database.col(i) = db.signals().col(c) * scale;
    for (size_t k = 0; k < keys.size(); ++k) queries(k, i) = static_cast<float>(sketch.values(keys[k], c)) * scale;
  }
  const Eigen::VectorXf norms = database.rowwise().squaredNorm();
  std::vector<int> rows(keys.size(), 0);
  for (size_t k = 0; k < keys.size(); ++k) {
    const Eigen::VectorXf d = norms - 2.0f * (database * queries.row(k).transpose());
    Eigen::Index best = 0;
    d.minCoeff(&best);
    rows[k] = static_cast<int>(best);
    for (int c : unkeyed) out(keys[k], c) = db.signals()(best, c);
  }
  for (int c : unkeyed) LerpBetweenKeys(out.middleCols(c, 1), keys);
  return rows;
}

}  // namespace mocapfill
