// Building a PcaModel from a motion database (thesis chapter 5): selecting the clips of
// some behaviours (behaviour-specific models, after Safonova et al. 2004), weighting the
// channels so distances approximate joint displacements in centimetres, and estimating the
// basis.
#pragma once

#include <string>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/core/pca_model.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"
#include "processing/pca/pca_basis.h"

namespace mocapfill {

struct PcaModelOptions {
  PcaBasisOptions basis;  // variance kept, component cap, pose or window PCA
  // Behaviour labels selecting the database clips; empty = every clip. A label "value"
  // matches a clip having any label equal to value (Bandai-Namco: content "walk", style
  // "happy"); "key=value" matches only that label key. A clip is used when any label matches.
  std::vector<std::string> labels;
  // Root velocity and yaw-rate features are weighted as the displacement (cm) they cause
  // over this horizon (s, > 0), so they weigh like a few frames of joint motion.
  double root_rate_horizon_s = 0.1;

  Status Validate() const;
};

// Per pose-channel weights for a skeleton (pose_dim = 3J + num_root_features entries):
// tangent channels of joint j: the extent (cm) of the rest-pose subtree j moves, i.e. the
// largest distance from j to a descendant or end site, at least 1 cm; root features:
// height in cm (x100), planar velocities x 100 x horizon, yaw rate x horizon x the root's
// extent in cm. `root_joint` -1 means no root features.
Eigen::VectorXd PcaChannelWeights(const Skeleton& skeleton, int root_joint, int num_root_features,
                                  double root_rate_horizon_s);

// True when `clip_labels` match the selection (see PcaModelOptions::labels).
bool ClipMatchesLabels(const ClipLabels& clip_labels, const std::vector<std::string>& selection);

// Builds a model from the selected clips of `database`. Errors: invalid options
// (kInvalidArgument), no clip matching the labels (kInvalidArgument naming them), and the
// errors of EstimatePcaBasis.
Result<PcaModel> BuildPcaModel(const MotionDatabase& database, const PcaModelOptions& options);

}  // namespace mocapfill
