#include "processing/pca/pca_model_builder.h"

#include <algorithm>
#include <cmath>

#include "processing/core/kinematics.h"

namespace mocapfill {

namespace {

// Distance from each joint to the farthest point (descendant joint or end site) of its
// rest-pose subtree, metres: every point is charged to all of its ancestors.
std::vector<double> SubtreeExtents(const Skeleton& skeleton) {
  const int n = skeleton.num_joints();
  const MotionClip rest = MotionClip::RestPose(skeleton, 1, 30.0);
  WorldPose pose;
  ComputeWorldPose(skeleton, rest, 0, pose);
  std::vector<double> extent(n, 0.0);
  const auto charge = [&](int joint, const Eigen::Vector3d& point, bool include_self) {
    for (int a = include_self ? joint : skeleton.parent(joint); a != kNoParent; a = skeleton.parent(a))
      extent[a] = std::max(extent[a], (point - pose.positions[a]).norm());
  };
  for (int j = 0; j < n; ++j) {
    charge(j, pose.positions[j], false);
    if (const auto& end = skeleton.joint(j).end_site) charge(j, pose.positions[j] + pose.rotations[j] * *end, true);
  }
  return extent;
}

}  // namespace

Status PcaModelOptions::Validate() const {
  RETURN_IF_ERROR(basis.Validate().WithContext("basis"));
  if (!(root_rate_horizon_s > 0.0 && std::isfinite(root_rate_horizon_s)))
    return InvalidArgument("root_rate_horizon_s must be finite and > 0");
  for (const std::string& label : labels)
    if (label.empty() || label.front() == '=' || label.back() == '=')
      return InvalidArgument("labels: '" + label + "' is not a label or key=value");
  return OkStatus();
}

Eigen::VectorXd PcaChannelWeights(const Skeleton& skeleton, int root_joint, int num_root_features,
                                  double root_rate_horizon_s) {
  constexpr double kCmPerM = 100.0;
  constexpr double kMinWeightCm = 1.0;  // leaf joints without end sites still get a say
  const std::vector<double> extent = SubtreeExtents(skeleton);
  const int joints = skeleton.num_joints();
  Eigen::VectorXd weights(3 * joints + std::max(num_root_features, 0));
  for (int j = 0; j < joints; ++j) weights.segment<3>(3 * j).setConstant(std::max(kMinWeightCm, kCmPerM * extent[j]));
  if (root_joint >= 0 && num_root_features > 0) {
    const double root_cm = std::max(kMinWeightCm, kCmPerM * extent[root_joint]);
    const double rate_weights[] = {kCmPerM, kCmPerM * root_rate_horizon_s, kCmPerM * root_rate_horizon_s,
                                   root_rate_horizon_s * root_cm};
    for (int f = 0; f < num_root_features; ++f) weights[3 * joints + f] = f < 4 ? rate_weights[f] : 1.0;
  }
  return weights;
}

bool ClipMatchesLabels(const ClipLabels& clip_labels, const std::vector<std::string>& selection) {
  if (selection.empty()) return true;
  for (const std::string& wanted : selection) {
    const size_t eq = wanted.find('=');
    for (const auto& [key, value] : clip_labels) {
      if (key == "file") continue;  // a path is not a behaviour
      if (eq == std::string::npos ? value == wanted : (key == wanted.substr(0, eq) && value == wanted.substr(eq + 1)))
        return true;
    }
  }
  return false;
}

Result<PcaModel> BuildPcaModel(const MotionDatabase& database, const PcaModelOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  std::vector<int> selected;
  int rows = 0;
  for (int i = 0; i < database.num_clips(); ++i)
    if (ClipMatchesLabels(database.clip(i).labels, options.labels)) {
      selected.push_back(i);
      rows += database.clip(i).num_frames;
    }
  if (selected.empty()) {
    std::string list;
    for (const std::string& l : options.labels) list += (list.empty() ? "" : ",") + l;
    return InvalidArgument("no database clip has any of the labels " + list);
  }
  PcaModel model;
  const Skeleton& skeleton = database.skeleton();
  for (int j = 0; j < skeleton.num_joints(); ++j) model.joint_names.push_back(skeleton.name(j));
  model.joint_means = database.joint_means();
  model.root_joint = database.root_joint();
  model.num_root_features = database.num_channels() - 3 * skeleton.num_joints();
  model.sample_rate_hz = database.rate_hz();
  model.channel_weights =
      PcaChannelWeights(skeleton, model.root_joint, model.num_root_features, options.root_rate_horizon_s);
  model.labels = options.labels;

  Eigen::MatrixXd poses(rows, model.pose_dim());
  std::vector<int> lengths;
  int row = 0;
  for (int i : selected) {
    const ClipRange& clip = database.clip(i);
    poses.middleRows(row, clip.num_frames) = database.ClipRows(database.signals(), i).cast<double>();
    row += clip.num_frames;
    lengths.push_back(clip.num_frames);
    model.clips.push_back(clip.name);
  }
  poses.array().rowwise() *= model.channel_weights.transpose().array();
  RETURN_IF_ERROR(EstimatePcaBasis(poses, lengths, options.basis, model));
  return model;
}

}  // namespace mocapfill
