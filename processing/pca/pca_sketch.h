// PCA methods on a keyframed sketch clip:
//  - FillMissingJointsPca: the `pca` fill method. Per frame, the closed-form conditional
//    mean of the unkeyed joints given the keyed joints (densified, as the sketch clip holds
//    them at every frame) and the root features.
//  - FitSketchToKeys: the Ceres fit (pca_fit.h) with keys taken from the sketch's keyed
//    frames, optional world position keys (feet, hands), and an optional guide clip (the
//    fragment result in the hybrid pipeline) for the unkeyed joints.
// A joint is keyed when the sketch's keys list rotation frames for it; the motion root's
// features are keyed where the root has rotation or translation keys.
#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/pca_model.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"
#include "processing/pca/closed_form_fit.h"
#include "processing/pca/ceres_fit/pca_fit.h"

namespace mocapfill {

struct PcaFillOptions {
  ClosedFormOptions closed_form;  // observation noise of the keyed channels
  Status Validate() const { return closed_form.Validate().WithContext("closed_form"); }
};

// Returns the sketch with every model joint that has no rotation keys replaced by the
// closed-form reconstruction; keyed joints, the root trajectory and all keys are kept.
// Errors: invalid options/model, model joints missing from the skeleton, a window model,
// a sketch whose rate differs from the model's by more than 1e-6 relative (kInvalidArgument).
Result<MotionClip> FillMissingJointsPca(const PcaModel& model, const Skeleton& skeleton, const MotionClip& sketch,
                                        const PcaFillOptions& options);

// A world position key named by joint.
struct SketchPositionKey {
  int frame = 0;
  std::string joint;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
};

struct PcaSketchFitOptions {
  PcaFitOptions fit;
  // Full-pose variant: keys hold exactly. Default: subspace variant (keys within s_key).
  bool full_pose = false;
  // Subspace variant only: key rotations through the geodesic residual instead of the
  // (linear) tangent-channel residual; the root's features stay linear keys.
  bool geodesic_keys = false;
  Status Validate() const;
};

struct PcaSketchFit {
  MotionClip clip;        // the fitted clip (sketch's root trajectory, keys and name kept)
  PcaFitResult fit;       // coefficients, pose vectors, solver report, stage timings
  double encode_s = 0.0;  // sketch (and guide) to pose vectors
  double decode_s = 0.0;  // pose vectors to clip
};

// Fits the model to the sketch's keys. `guide` (optional, same skeleton, frame count and
// rate as the sketch) pulls unkeyed joints towards it, except joints on the chain from the
// root to a position-keyed joint (the position keys decide those). Errors: as FillMissingJointsPca,
// plus unknown joint names or out-of-range frames in position keys, and FitPcaToKeys /
// FitFullPoseToKeys errors.
Result<PcaSketchFit> FitSketchToKeys(const PcaModel& model, const Skeleton& skeleton, const MotionClip& sketch,
                                     const std::vector<SketchPositionKey>& position_keys, const MotionClip* guide,
                                     const PcaSketchFitOptions& options);

}  // namespace mocapfill
