#include "processing/pca/pca_sketch.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "processing/core/closest_names.h"
#include "processing/core/stopwatch.h"
#include "processing/motion/tangent_space.h"
#include "processing/pca/pca_clip.h"
#include "processing/pca/pca_layout.h"

namespace mocapfill {

namespace {

using Clock = std::chrono::steady_clock;

Status CheckSketch(const PcaModel& model, const Skeleton& skeleton, const MotionClip& sketch) {
  RETURN_IF_ERROR(RequireUniform(sketch, "pca"));
  RETURN_IF_ERROR(ValidatePcaModel(model).WithContext("pca model"));
  if (model.window_frames != 1)
    return InvalidArgument("filling and fitting need a pose model; this model has windows of " +
                           std::to_string(model.window_frames) + " frames");
  RETURN_IF_ERROR(sketch.Validate(skeleton).WithContext("sketch '" + sketch.name + "'"));
  if (sketch.num_frames < 1) return InvalidArgument("sketch '" + sketch.name + "' has no frames");
  if (std::abs(sketch.sample_rate_hz / model.sample_rate_hz - 1.0) > 1e-6)
    return InvalidArgument("sketch '" + sketch.name + "' is sampled at " + std::to_string(sketch.sample_rate_hz) +
                           " Hz but the model at " + std::to_string(model.sample_rate_hz) + " Hz; resample it first");
  return OkStatus();
}

// Model joints the sketch keys (rotation keys at any frame), as model indices.
std::vector<int> KeyedModelJoints(const PcaModel& model, const PcaBinding& binding, const MotionClip& sketch) {
  std::vector<int> keyed;
  for (int m = 0; m < model.num_joints(); ++m)
    if (!sketch.keys[binding.model_to_skeleton[m]].rotation_frames.empty()) keyed.push_back(m);
  return keyed;
}

// Frames at which the motion root is keyed (rotation or translation), sorted, unique.
std::vector<int> RootKeyFrames(const PcaModel& model, const PcaBinding& binding, const MotionClip& sketch) {
  if (model.root_joint < 0) return {};
  const JointKeys& keys = sketch.keys[binding.model_to_skeleton[model.root_joint]];
  std::vector<int> frames = keys.rotation_frames;
  frames.insert(frames.end(), keys.translation_frames.begin(), keys.translation_frames.end());
  std::sort(frames.begin(), frames.end());
  frames.erase(std::unique(frames.begin(), frames.end()), frames.end());
  return frames;
}

void MarkRootFeatures(const PcaModel& model, int frame, ChannelMask& mask) {
  if (model.num_root_features > 0) mask.row(frame).tail(model.num_root_features) = true;
}

// Sketch keys as a (frames x pose_dim) mask: keyed joints at their rotation key frames,
// root features at the root's key frames.
ChannelMask KeyMask(const PcaModel& model, const PcaBinding& binding, const MotionClip& sketch) {
  ChannelMask mask = ChannelMask::Constant(sketch.num_frames, model.pose_dim(), false);
  for (int m = 0; m < model.num_joints(); ++m)
    for (int f : sketch.keys[binding.model_to_skeleton[m]].rotation_frames)
      if (f >= 0 && f < sketch.num_frames) mask.row(f).segment<3>(3 * m) = true;
  for (int f : RootKeyFrames(model, binding, sketch))
    if (f >= 0 && f < sketch.num_frames) MarkRootFeatures(model, f, mask);
  return mask;
}

Result<FitKinematics> MakeKinematics(const PcaModel& model, const PcaBinding& binding, const Skeleton& skeleton,
                                     const MotionClip& sketch) {
  FitKinematics kin;
  kin.parents = binding.model_parents;
  const int joints = model.num_joints();
  kin.translations_m.resize(static_cast<size_t>(sketch.num_frames) * joints);
  for (int f = 0; f < sketch.num_frames; ++f)
    for (int m = 0; m < joints; ++m) {
      const int s = binding.model_to_skeleton[m];
      const int parent = skeleton.parent(s);
      const Eigen::Vector3d scale = parent == kNoParent ? Eigen::Vector3d::Ones() : skeleton.joint(parent).rest_scale;
      kin.translations_m[static_cast<size_t>(f) * joints + m] = scale.cwiseProduct(sketch.translation(f, s));
    }
  if (model.root_joint >= 0) {
    const RootTrajectory trajectory =
        ExtractRootTrajectory(skeleton, sketch, binding.model_to_skeleton[model.root_joint]);
    kin.root_heading_rad = trajectory.heading_rad;
    kin.root_position_m = trajectory.position_m;
  }
  return kin;
}

Result<std::vector<PositionKey>> ResolvePositionKeys(const PcaModel& model, const std::vector<SketchPositionKey>& keys) {
  std::vector<PositionKey> out;
  for (const SketchPositionKey& key : keys) {
    const auto it = std::find(model.joint_names.begin(), model.joint_names.end(), key.joint);
    if (it == model.joint_names.end())
      return InvalidArgument("position key on unknown joint '" + key.joint + "' (closest: " +
                             QuotedClosestNames(key.joint, model.joint_names) + ")");
    out.push_back({key.frame, static_cast<int>(it - model.joint_names.begin()), key.position_m});
  }
  return out;
}

// Geodesic keys for every keyed model joint except the motion root (its tilt is a derived
// quantity and stays a channel key); removes those joints' channels from the key mask.
std::vector<RotationKey> TakeGeodesicKeys(const PcaModel& model, const PcaBinding& binding, const MotionClip& sketch,
                                          ChannelMask& mask) {
  std::vector<RotationKey> keys;
  for (int m = 0; m < model.num_joints(); ++m) {
    if (m == model.root_joint) continue;
    const int s = binding.model_to_skeleton[m];
    for (int f : sketch.keys[s].rotation_frames) {
      if (f < 0 || f >= sketch.num_frames) continue;
      keys.push_back({f, m, sketch.rotation(f, s)});
      mask.row(f).segment<3>(3 * m) = false;
    }
  }
  return keys;
}

}  // namespace

Result<MotionClip> FillMissingJointsPca(const PcaModel& model, const Skeleton& skeleton, const MotionClip& sketch,
                                        const PcaFillOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  RETURN_IF_ERROR(CheckSketch(model, skeleton, sketch));
  ASSIGN_OR_RETURN(const PcaBinding binding, BindPcaModel(model, skeleton));
  const EncodedClip encoded = EncodeClip(model, binding, skeleton, sketch);
  const std::vector<int> keyed = KeyedModelJoints(model, binding, sketch);
  // The sketch holds keyed joints densified at every frame: all of those frames condition.
  ChannelMask observed = ChannelMask::Constant(sketch.num_frames, model.pose_dim(), false);
  for (int m : keyed) observed.middleCols<3>(3 * m) = true;
  if (!RootKeyFrames(model, binding, sketch).empty())
    for (int f = 0; f < sketch.num_frames; ++f) MarkRootFeatures(model, f, observed);
  ASSIGN_OR_RETURN(const Eigen::MatrixXd filled, ClosedFormFill(model, encoded.poses, observed, options.closed_form));
  return DecodeClip(model, binding, skeleton, encoded, filled, sketch, keyed);
}

Status PcaSketchFitOptions::Validate() const {
  RETURN_IF_ERROR(fit.Validate().WithContext("fit"));
  if (full_pose && geodesic_keys) return InvalidArgument("geodesic_keys applies to the subspace variant only");
  return OkStatus();
}

Result<PcaSketchFit> FitSketchToKeys(const PcaModel& model, const Skeleton& skeleton, const MotionClip& sketch,
                                     const std::vector<SketchPositionKey>& position_keys, const MotionClip* guide,
                                     const PcaSketchFitOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  RETURN_IF_ERROR(CheckSketch(model, skeleton, sketch));
  if (guide != nullptr) {
    RETURN_IF_ERROR(guide->Validate(skeleton).WithContext("guide '" + guide->name + "'"));
    if (guide->num_frames != sketch.num_frames)
      return InvalidArgument("guide has " + std::to_string(guide->num_frames) + " frames, the sketch " +
                             std::to_string(sketch.num_frames));
  }
  ASSIGN_OR_RETURN(const PcaBinding binding, BindPcaModel(model, skeleton));
  PcaSketchFit out;
  Clock::time_point start = Clock::now();
  const EncodedClip encoded = EncodeClip(model, binding, skeleton, sketch);
  PcaKeyProblem problem;
  problem.num_frames = sketch.num_frames;
  problem.key_values = encoded.poses;
  problem.key_mask = KeyMask(model, binding, sketch);
  if (options.geodesic_keys) problem.rotation_keys = TakeGeodesicKeys(model, binding, sketch, problem.key_mask);
  ASSIGN_OR_RETURN(problem.position_keys, ResolvePositionKeys(model, position_keys));
  if (!problem.position_keys.empty()) {
    ASSIGN_OR_RETURN(problem.kinematics, MakeKinematics(model, binding, skeleton, sketch));
  }
  const std::vector<int> keyed = KeyedModelJoints(model, binding, sketch);
  if (guide != nullptr) {
    problem.guide_values = EncodeClip(model, binding, skeleton, *guide).poses;
    problem.guide_mask = ChannelMask::Constant(sketch.num_frames, model.pose_dim(), true);
    for (int m : keyed) problem.guide_mask.middleCols<3>(3 * m) = false;
    if (model.num_root_features > 0) problem.guide_mask.rightCols(model.num_root_features) = false;
    // Positions decide the chains they key: a guide there would pull the feet off their keys.
    for (const PositionKey& key : problem.position_keys)
      for (int m = key.joint; m >= 0; m = binding.model_parents[m]) problem.guide_mask.middleCols<3>(3 * m) = false;
  }
  out.encode_s = SecondsSince(start);
  if (options.full_pose) {
    ASSIGN_OR_RETURN(out.fit, FitFullPoseToKeys(model, problem, options.fit));
  } else {
    ASSIGN_OR_RETURN(out.fit, FitPcaToKeys(model, problem, options.fit));
  }
  start = Clock::now();
  ASSIGN_OR_RETURN(out.clip, DecodeClip(model, binding, skeleton, encoded, out.fit.poses, sketch));
  out.decode_s = SecondsSince(start);
  return out;
}

}  // namespace mocapfill
