#include "processing/pca/pca_layout.h"

#include <cmath>

#include "processing/core/rotation.h"
#include "processing/motion/tangent_space.h"

namespace mocapfill {

std::string ChannelName(const PcaModel& model, int channel) {
  const int joint = ChannelJoint(model, channel);
  if (joint >= 0) return model.joint_names[joint] + "." + "xyz"[channel % 3];
  const int feature = channel - 3 * model.num_joints();
  if (feature < kNumRootFeatures) return RootFeatureName(feature);
  return "root.feature" + std::to_string(feature);
}

Eigen::VectorXd ChannelSigmas(const PcaModel& model, double tangent_sigma_deg, double root_sigma) {
  Eigen::VectorXd sigma(model.pose_dim());
  for (int c = 0; c < model.pose_dim(); ++c)
    sigma[c] = ChannelJoint(model, c) >= 0 ? tangent_sigma_deg * kRadPerDeg * model.channel_weights[c] : root_sigma;
  return sigma;
}

}  // namespace mocapfill
