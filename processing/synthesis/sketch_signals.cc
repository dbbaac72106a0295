#include "processing/synthesis/sketch_signals.h"

#include <algorithm>
#include <set>

#include "processing/core/median.h"

namespace mocapfill {

namespace {

template <typename Matrix>
void LerpImpl(Eigen::Ref<Matrix> block, const std::vector<int>& keys) {
  const int rows = static_cast<int>(block.rows());
  if (keys.empty() || rows == 0) return;
  for (int f = 0; f < keys.front(); ++f) block.row(f) = block.row(keys.front());
  for (int f = keys.back() + 1; f < rows; ++f) block.row(f) = block.row(keys.back());
  for (size_t k = 0; k + 1 < keys.size(); ++k) {
    const int a = keys[k], b = keys[k + 1];
    for (int f = a + 1; f < b; ++f) {
      const double u = double(f - a) / (b - a);
      block.row(f) = (1.0 - u) * block.row(a) + u * block.row(b);
    }
  }
}

template <typename Matrix>
void IntervalMeanImpl(Eigen::Ref<Matrix> block, const std::vector<int>& keys) {
  const int rows = static_cast<int>(block.rows());
  if (keys.empty() || rows == 0) return;
  std::vector<int> cuts = keys;
  if (cuts.front() != 0) cuts.insert(cuts.begin(), 0);
  if (cuts.back() != rows - 1) cuts.push_back(rows - 1);
  for (size_t k = 0; k + 1 < cuts.size(); ++k) {
    const int a = cuts[k], b = cuts[k + 1];
    const auto mean = block.middleRows(a, b - a).colwise().mean().eval();
    for (int f = a; f < b; ++f) block.row(f) = mean;
  }
  if (cuts.size() >= 2) block.row(rows - 1) = block.row(rows - 2);
}

int MedianSpacing(const std::vector<std::vector<int>>& key_frames) {
  std::vector<int> gaps;
  for (const std::vector<int>& keys : key_frames)
    for (size_t k = 1; k < keys.size(); ++k) gaps.push_back(keys[k] - keys[k - 1]);
  if (gaps.empty()) return 1;
  return std::max(1, UpperMedian(std::move(gaps)));
}

}  // namespace

void LerpBetweenKeys(Eigen::Ref<Eigen::MatrixXd> block, const std::vector<int>& keys) {
  LerpImpl<Eigen::MatrixXd>(block, keys);
}
void LerpBetweenKeys(Eigen::Ref<Eigen::MatrixXf> block, const std::vector<int>& keys) {
  LerpImpl<Eigen::MatrixXf>(block, keys);
}
void IntervalMeanBetweenKeys(Eigen::Ref<Eigen::MatrixXf> block, const std::vector<int>& keys) {
  IntervalMeanImpl<Eigen::MatrixXf>(block, keys);
}
void IntervalMeanBetweenKeys(Eigen::Ref<Eigen::MatrixXd> block, const std::vector<int>& keys) {
  IntervalMeanImpl<Eigen::MatrixXd>(block, keys);
}

std::vector<int> PhaseKeys(int frames, int spacing, int phase) {
  std::vector<int> keys;
  if (frames <= 0) return keys;
  keys.push_back(0);
  for (int f = phase; f < frames; f += std::max(1, spacing))
    if (f > 0) keys.push_back(f);
  if (keys.back() != frames - 1) keys.push_back(frames - 1);
  return keys;
}

bool IsRootVelocityFeature(int feature) {
  return feature == kRootForward || feature == kRootLateral || feature == kRootYawRate;
}

Result<SketchSignals> MakeSketchSignals(const MotionDatabase& db, const MotionClip& sketch) {
  const Skeleton& skeleton = db.skeleton();
  RETURN_IF_ERROR(sketch.Validate(skeleton).WithContext("sketch"));
  RETURN_IF_ERROR(RequireUniform(sketch, "sketch"));
  const int nj = skeleton.num_joints(), root = db.root_joint();
  SketchSignals s;
  s.frames = sketch.num_frames;
  s.num_joints = nj;
  s.raw = DecomposeClip(skeleton, sketch, db.reference());
  const int features = static_cast<int>(s.raw.root_features.cols());
  s.values.resize(s.frames, 3 * nj + features);
  s.values.leftCols(3 * nj) = s.raw.tangent;
  if (features > 0) s.values.rightCols(features) = s.raw.root_features;
  s.keyed.assign(s.values.cols(), 0);
  s.key_frames.assign(s.values.cols(), {});
  for (int j = 0; j < nj; ++j) {
    const std::vector<int>& keys = sketch.keys[j].rotation_frames;
    if (keys.empty()) continue;
    for (int a = 0; a < 3; ++a) {
      s.keyed[3 * j + a] = 1;
      s.key_frames[3 * j + a] = keys;
    }
    LerpBetweenKeys(s.values.middleCols(3 * j, 3), keys);
  }
  if (root >= 0 && features > 0 && !sketch.keys[root].translation_frames.empty()) {
    const std::vector<int>& keys = sketch.keys[root].translation_frames;
    for (int f = 0; f < features; ++f) {
      const int c = 3 * nj + f;
      s.keyed[c] = 1;
      s.key_frames[c] = keys;
      if (IsRootVelocityFeature(f)) {
        IntervalMeanBetweenKeys(s.values.middleCols(c, 1), keys);
      } else {
        LerpBetweenKeys(s.values.middleCols(c, 1), keys);
      }
    }
  }
  std::set<int> all;
  for (const std::vector<int>& keys : s.key_frames) all.insert(keys.begin(), keys.end());
  if (all.empty()) return InvalidData("the sketch has no keyed joint: nothing to fill from");
  s.all_key_frames.assign(all.begin(), all.end());
  s.key_spacing = MedianSpacing(s.key_frames);
  return s;
}

}  // namespace mocapfill
