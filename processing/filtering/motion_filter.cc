#include "processing/filtering/motion_filter.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace mocapfill {

Status MultiresFilterOptions::Validate() const {
  RETURN_IF_ERROR(pyramid.Validate());
  for (size_t k = 0; k < gains.band_gains.size(); ++k)
    if (!std::isfinite(gains.band_gains[k]))
      return InvalidArgument("multires filter: gain " + std::to_string(k) + " is not finite");
  if (!std::isfinite(gains.residual_gain)) return InvalidArgument("multires filter: residual gain is not finite");
  return OkStatus();
}

Result<MotionClip> MultiresFilter(const Skeleton& skeleton, const MotionClip& clip,
                                  const MultiresFilterOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  RETURN_IF_ERROR(clip.Validate(skeleton));
  RETURN_IF_ERROR(RequireUniform(clip, "filter"));
  for (int j : options.joints)
    if (j < 0 || j >= skeleton.num_joints())
      return InvalidArgument("multires filter: joint index " + std::to_string(j) + " is out of range");

  TangentReference own_reference;
  const TangentReference* reference = options.reference;
  if (reference == nullptr) {
    const MotionClip* clips[] = {&clip};
    own_reference = ComputeTangentReference(skeleton, clips, FindMotionRoot(skeleton, clips));
    reference = &own_reference;
  }
  if (static_cast<int>(reference->joint_means.size()) != skeleton.num_joints())
    return InvalidArgument("multires filter: the reference has " + std::to_string(reference->joint_means.size()) +
                           " joint means, the skeleton has " + std::to_string(skeleton.num_joints()) + " joints");

  ClipSignals signals = DecomposeClip(skeleton, clip, *reference);
  std::vector<int> joints = options.joints;
  if (joints.empty())
    for (int j = 0; j < skeleton.num_joints(); ++j) joints.push_back(j);
  std::sort(joints.begin(), joints.end());
  joints.erase(std::unique(joints.begin(), joints.end()), joints.end());
  const bool with_root =
      reference->root_joint >= 0 && std::binary_search(joints.begin(), joints.end(), reference->root_joint);

  // Gather the selected channels into one matrix so a single pyramid filters them all.
  const int tangent_columns = 3 * static_cast<int>(joints.size());
  Eigen::MatrixXd selected(clip.num_frames, tangent_columns + (with_root ? kNumRootFeatures : 0));
  for (size_t i = 0; i < joints.size(); ++i) selected.middleCols<3>(3 * i) = signals.tangent.middleCols<3>(3 * joints[i]);
  if (with_root) selected.rightCols<kNumRootFeatures>() = signals.root_features;

  ASSIGN_OR_RETURN(Eigen::MatrixXd filtered, FilterBands(selected, clip.sample_rate_hz, options.pyramid, options.gains));
  for (size_t i = 0; i < joints.size(); ++i) signals.tangent.middleCols<3>(3 * joints[i]) = filtered.middleCols<3>(3 * i);
  if (with_root) signals.root_features = filtered.rightCols<kNumRootFeatures>();
  return ComposeClip(skeleton, signals, *reference, clip);
}

}  // namespace mocapfill
