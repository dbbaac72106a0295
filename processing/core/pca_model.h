// The principal component model of a motion database (thesis chapter 5) as plain data.
//
// It lives in core, beside MotionClip, because both the algorithms (processing/pca) and
// the .pca file format (formats/pca) need it and formats must not depend on processing.
// The model is self-contained: besides the linear Gaussian model (mean, components,
// variances) it carries the tangent-space reference and channel weights of the database,
// so a clip of the same skeleton can be projected without the database at hand.
//
// Vector layout. A pose vector y (pose_dim entries) holds, for every joint j in model
// order, the weighted tangent coordinates w_j * Log(Rbar_j^-1 R_j) (3 entries, radians
// times weight), followed by num_root_features weighted root features (height, planar
// velocity, yaw rate; see processing/core/signal_layout.h). A window model
// (window_frames = W > 1) stacks W consecutive pose vectors, oldest first, so its vectors
// have W * pose_dim entries. Weights make squared distances approximate squared joint
// displacements in centimetres (5a.2), which is what PCA should spend its variance on.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "processing/core/status.h"

namespace mocapfill {

struct PcaModel {
  // Skeleton the model describes, matched by joint name when a clip is projected.
  std::vector<std::string> joint_names;
  // Tangent reference (TangentReference in processing/core/signal_layout.h): per joint the
  // mean local rotation; for root_joint the mean world tilt. root_joint = -1: no root split.
  std::vector<Eigen::Quaterniond> joint_means;
  int root_joint = -1;
  int num_root_features = 0;      // weighted root-feature channels after the 3J tangent ones
  double sample_rate_hz = 30.0;   // rate of the database; smoothness statistics are per frame at it

  // pose_dim entries: y = channel_weights .* signal. Tangent channels: cm per radian
  // (the extent of the chain the joint moves); root features: see BuildPcaModel.
  Eigen::VectorXd channel_weights;

  int window_frames = 1;          // 1 = pose PCA; W > 1 = window PCA of W stacked poses
  Eigen::VectorXd mean;           // dim() entries
  Eigen::MatrixXd components;     // dim() x K, orthonormal columns, decreasing variance
  Eigen::VectorXd variances;      // K eigenvalues lambda_k (weighted units squared)
  Eigen::VectorXd spectrum;       // all dim() eigenvalues, decreasing (explained variance, PPCA residual)
  // Per entry of the vector (dim() entries): the database variance the K components leave
  // unexplained, diag(S - U Lambda U^T). Observations of a channel are trusted no more
  // than the model can reproduce them (closed-form fit).
  Eigen::VectorXd residual_variance;
  // Root-mean-square second difference over database frames (per frame, at sample_rate_hz):
  // of each coefficient c_k (K entries) and of each pose channel (pose_dim entries). These
  // are the smoothness sigmas s_acc of the Ceres key fit (processing/pca/ceres_fit/pca_fit.h): a
  // database statistic, so the smoothness weight carries over between frame rates.
  Eigen::VectorXd coefficient_accel_rms;
  Eigen::VectorXd channel_accel_rms;

  int num_samples = 0;              // vectors the model was estimated from
  std::vector<std::string> labels;  // behaviour labels that selected the database clips; empty = all
  std::vector<std::string> clips;   // names of the clips the model was built from

  int num_joints() const { return static_cast<int>(joint_names.size()); }
  int pose_dim() const { return 3 * num_joints() + num_root_features; }
  int dim() const { return window_frames * pose_dim(); }
  int num_components() const { return static_cast<int>(components.cols()); }

  // Structural consistency: sizes agree, finite numbers, unit joint means, orthonormal
  // components, positive variances, weights and smoothness sigmas. Readers and every
  // algorithm check this first; kInvalidData names the first broken field.
  Status Validate() const;
};

}  // namespace mocapfill
