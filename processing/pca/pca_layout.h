// Channels of a PcaModel's pose vector (see processing/core/pca_model.h for the layout):
// names, owning joints, and per-channel sigmas in weighted units, which is how every
// tolerance given in degrees or centimetres by a user reaches the PCA algorithms.
#pragma once

#include <Eigen/Core>
#include <string>

#include "processing/core/pca_model.h"
#include "processing/core/status.h"

namespace mocapfill {

// (frames x channels) flags: true where a channel is observed (keyed, guided, ...).
using ChannelMask = Eigen::Array<bool, Eigen::Dynamic, Eigen::Dynamic>;

// Joint owning pose channel `channel`, or -1 for a root-feature channel.
inline int ChannelJoint(const PcaModel& model, int channel) {
  return channel < 3 * model.num_joints() ? channel / 3 : -1;
}

// "<joint>.x" / ".y" / ".z" for tangent channels, "root.<feature>" for root features
// (names of processing/motion/tangent_space.h RootFeatureName).
std::string ChannelName(const PcaModel& model, int channel);

// Per pose channel sigma in weighted units: tangent channels tangent_sigma_deg (converted to
// radians) times the channel weight; root-feature channels root_sigma, already weighted
// (weighted root features are centimetre-like, see BuildPcaModel).
Eigen::VectorXd ChannelSigmas(const PcaModel& model, double tangent_sigma_deg, double root_sigma);

// Structural consistency of a model (kInvalidData naming the first broken field).
inline Status ValidatePcaModel(const PcaModel& model) { return model.Validate(); }

}  // namespace mocapfill
