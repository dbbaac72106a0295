#include "processing/pca/pca_clip.h"

#include <string>

namespace mocapfill {

Result<PcaBinding> BindPcaModel(const PcaModel& model, const Skeleton& skeleton) {
  PcaBinding binding;
  binding.skeleton_to_model.assign(skeleton.num_joints(), -1);
  for (int m = 0; m < model.num_joints(); ++m) {
    const std::optional<int> s = skeleton.Find(model.joint_names[m]);
    if (!s) return InvalidArgument("skeleton has no joint '" + model.joint_names[m] + "' that the PCA model needs");
    binding.model_to_skeleton.push_back(*s);
    binding.skeleton_to_model[*s] = m;
  }
  for (int m = 0; m < model.num_joints(); ++m) {
    const int parent = skeleton.parent(binding.model_to_skeleton[m]);
    const int model_parent = parent == kNoParent ? -1 : binding.skeleton_to_model[parent];
    if (parent != kNoParent && model_parent < 0)
      return InvalidArgument("joint '" + model.joint_names[m] + "' has parent '" + skeleton.name(parent) +
                             "', which the PCA model does not know");
    binding.model_parents.push_back(model_parent);
  }
  binding.reference.joint_means.assign(skeleton.num_joints(), Eigen::Quaterniond::Identity());
  for (int m = 0; m < model.num_joints(); ++m) binding.reference.joint_means[binding.model_to_skeleton[m]] = model.joint_means[m];
  binding.reference.root_joint = model.root_joint >= 0 ? binding.model_to_skeleton[model.root_joint] : -1;
  return binding;
}

EncodedClip EncodeClip(const PcaModel& model, const PcaBinding& binding, const Skeleton& skeleton,
                       const MotionClip& clip) {
  EncodedClip out;
  out.signals = DecomposeClip(skeleton, clip, binding.reference);
  const int joints = model.num_joints();
  out.poses.resize(clip.num_frames, model.pose_dim());
  for (int m = 0; m < joints; ++m)
    out.poses.middleCols<3>(3 * m) = out.signals.tangent.middleCols<3>(3 * binding.model_to_skeleton[m]);
  if (model.num_root_features > 0) out.poses.rightCols(model.num_root_features) = out.signals.root_features;
  out.poses.array().rowwise() *= model.channel_weights.transpose().array();
  return out;
}

Result<MotionClip> DecodeClip(const PcaModel& model, const PcaBinding& binding, const Skeleton& skeleton,
                              const EncodedClip& encoded, const Eigen::MatrixXd& poses, const MotionClip& like,
                              const std::vector<int>& keep_joints) {
  if (poses.rows() != like.num_frames || poses.cols() != model.pose_dim())
    return InvalidArgument("poses are " + std::to_string(poses.rows()) + " x " + std::to_string(poses.cols()) +
                           ", expected " + std::to_string(like.num_frames) + " x " + std::to_string(model.pose_dim()));
  if (!poses.allFinite()) return NumericalFailure("decoded poses contain a non-finite value");
  ClipSignals signals = encoded.signals;
  const Eigen::MatrixXd unweighted = poses.array().rowwise() / model.channel_weights.transpose().array();
  std::vector<bool> keep(model.num_joints(), false);
  for (int m : keep_joints) keep[m] = true;
  for (int m = 0; m < model.num_joints(); ++m)
    if (!keep[m]) signals.tangent.middleCols<3>(3 * binding.model_to_skeleton[m]) = unweighted.middleCols<3>(3 * m);
  ASSIGN_OR_RETURN(MotionClip out, ComposeClip(skeleton, signals, binding.reference, like));
  // Composition rebuilds every joint from its tangent; restore kept joints bit for bit.
  for (int m : keep_joints) {
    const int s = binding.model_to_skeleton[m];
    if (s == binding.reference.root_joint) continue;  // root pose is re-integrated; keep within rounding
    for (int f = 0; f < like.num_frames; ++f) out.rotation(f, s) = like.rotation(f, s);
  }
  out.MakeContinuous();
  return out;
}

}  // namespace mocapfill
