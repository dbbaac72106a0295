// Between clips and a PcaModel's weighted pose vectors: binding a model to a clip's
// skeleton (joints matched by name), encoding a clip (tangent coordinates about the
// model's reference, root features, channel weights) and decoding fitted or edited pose
// vectors back into a clip. Root heading and planar progression always come from the
// input clip, never from the model: a pose model holds no place or direction in the world.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/pca_model.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"
#include "processing/motion/tangent_space.h"

namespace mocapfill {

// How a model's joints sit in one skeleton.
struct PcaBinding {
  std::vector<int> model_to_skeleton;  // per model joint: skeleton joint index
  std::vector<int> skeleton_to_model;  // per skeleton joint: model joint index or -1
  std::vector<int> model_parents;      // per model joint: model index of its parent, -1 for a root
  TangentReference reference;          // skeleton-sized; joints outside the model: identity
};

// Matches model joints to skeleton joints by name. Errors (kInvalidArgument): a model joint
// missing from the skeleton, or a model joint whose skeleton parent is not a model joint
// (the hierarchy between model joints must be the model's). Skeleton joints the model does
// not know (e.g. end-site nodes) are allowed and keep their own rotations.
Result<PcaBinding> BindPcaModel(const PcaModel& model, const Skeleton& skeleton);

// A clip in the model's vector space.
struct EncodedClip {
  Eigen::MatrixXd poses;  // frames x pose_dim, weighted
  ClipSignals signals;    // the clip's own signals (root trajectory start, unweighted features)
};

// Encodes every frame of `clip` (which must be valid for `skeleton`).
EncodedClip EncodeClip(const PcaModel& model, const PcaBinding& binding, const Skeleton& skeleton,
                       const MotionClip& clip);

// Writes the tangent channels of `poses` (frames x pose_dim, weighted) into a copy of
// `like` (the clip that was encoded): model joints get Rbar_j Exp(y_j / w_j); the root
// features of `encoded` (the input's trajectory) are kept. Joints listed in `keep_joints`
// (model indices) keep their rotations from `like` exactly.
// Errors: size mismatch (kInvalidArgument), non-finite poses (kNumericalFailure).
Result<MotionClip> DecodeClip(const PcaModel& model, const PcaBinding& binding, const Skeleton& skeleton,
                              const EncodedClip& encoded, const Eigen::MatrixXd& poses, const MotionClip& like,
                              const std::vector<int>& keep_joints = {});

}  // namespace mocapfill
