#include "processing/synthesis/consensus_weights.h"

#include <algorithm>
#include <cmath>

#include "processing/core/kinematics.h"

namespace mocapfill {

Eigen::MatrixXf GroupPositions(const MotionDatabase& db, const std::vector<int>& group) {
  const Skeleton& skeleton = db.skeleton();
  auto in_group = [&](int j) { return std::find(group.begin(), group.end(), j) != group.end(); };
  std::vector<int> placed;
  for (int j = 0; j < skeleton.num_joints(); ++j)
    if (skeleton.parent(j) >= 0 && in_group(skeleton.parent(j))) placed.push_back(j);
  Eigen::MatrixXf table(db.num_frames(), 3 * placed.size());
  std::vector<Eigen::Quaterniond> rotation(skeleton.num_joints(), Eigen::Quaterniond::Identity());
  std::vector<Eigen::Vector3d> position(skeleton.num_joints(), Eigen::Vector3d::Zero());
  for (int f = 0; f < db.num_frames(); ++f) {
    for (size_t g = 0; g < group.size(); ++g) {
      const int j = group[g];
      const Eigen::Quaterniond local = db.LocalRotation(j, db.signals().row(f).segment<3>(3 * j).cast<double>());
      if (g == 0) {
        position[j].setZero();
        rotation[j] = local;
      } else {
        const int p = skeleton.parent(j);
        position[j] = position[p] + rotation[p] * RestOffset(skeleton, j);
        rotation[j] = rotation[p] * local;
      }
    }
    for (size_t k = 0; k < placed.size(); ++k) {
      const int j = placed[k], p = skeleton.parent(j);
      table.row(f).segment<3>(3 * k) = (position[p] + rotation[p] * RestOffset(skeleton, j)).cast<float>().transpose();
    }
  }
  return table;
}

std::vector<std::vector<double>> ConsensusWeights(const AssemblyInputs& in, const Eigen::MatrixXf& positions,
                                                  int iterations, double floor_m) {
  std::vector<std::vector<double>> weights =
      in.weights ? *in.weights : std::vector<std::vector<double>>(in.fragments->size());
  if (!in.weights)
    for (size_t i = 0; i < weights.size(); ++i)
      if (!(*in.candidates)[i].empty())
        weights[i] = DistanceWeights((*in.candidates)[i], BlendSet((*in.candidates)[i], in.leads[i], in.blend));
  const std::vector<std::vector<double>> start = weights;
  const int columns = static_cast<int>(positions.cols());
  if (columns == 0) return weights;
  const double joints = columns / 3.0;
  // Each candidate's positions averaged over its own fragment: they do not change between steps.
  std::vector<Eigen::MatrixXd> means(weights.size());
  double frames = 0.0;
  for (size_t i = 0; i < weights.size(); ++i) {
    const std::vector<Candidate>& cands = (*in.candidates)[i];
    if (cands.empty() || weights[i].size() < 2) continue;
    const std::vector<int> set = BlendSet(cands, in.leads[i], in.blend);
    means[i].resize(set.size(), columns);
    for (size_t k = 0; k < set.size(); ++k) {
      const DbFragment& g = in.mdb->fragments()[cands[set[k]].fragment];
      means[i].row(k) =
          positions.middleRows(in.mdb->Row(g.clip, g.first), g.last - g.first + 1).colwise().mean().cast<double>();
    }
    frames += (*in.fragments)[i].last - (*in.fragments)[i].first + 1;
  }
  if (frames <= 0.0) return weights;
  for (int step = 0; step < iterations; ++step) {
    // The take's consensus: each fragment's blend of its candidates' mean positions, averaged
    // over the fragments by their length (what the blended positions average to over the take,
    // up to the cross-fades).
    Eigen::RowVectorXd consensus = Eigen::RowVectorXd::Zero(columns);
    for (size_t i = 0; i < weights.size(); ++i) {
      if (means[i].rows() == 0) continue;
      const double length = (*in.fragments)[i].last - (*in.fragments)[i].first + 1;
      for (int k = 0; k < means[i].rows(); ++k) consensus += (length * weights[i][k] / frames) * means[i].row(k);
    }
    for (size_t i = 0; i < weights.size(); ++i) {
      if (means[i].rows() == 0) continue;
      double sum = 0.0;
      for (int k = 0; k < means[i].rows(); ++k) {
        const double distance = (means[i].row(k) - consensus).norm() / std::sqrt(joints);
        weights[i][k] = start[i][k] / std::max(floor_m, distance);
        sum += weights[i][k];
      }
      // Regression weights may be negative; a set whose reweighted sum vanishes keeps its own.
      if (!(sum > 1e-9)) {
        weights[i] = start[i];
        continue;
      }
      for (double& w : weights[i]) w /= sum;
    }
  }
  return weights;
}

}  // namespace mocapfill
