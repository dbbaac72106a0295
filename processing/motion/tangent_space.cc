#include "processing/motion/tangent_space.h"

#include <cmath>

#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"

namespace mocapfill {

namespace {

// World transform of joint j's parent at `frame` (identity for a root): the frame in which
// j's local transform lives. Follows ComputeWorldPose, including the parent's rest scale.
struct ParentFrame {
  Eigen::Vector3d position = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
};

// Ancestors of `joint`, root first.
std::vector<int> AncestorChain(const Skeleton& skeleton, int joint) {
  std::vector<int> chain;
  for (int p = skeleton.parent(joint); p != kNoParent; p = skeleton.parent(p)) chain.push_back(p);
  return {chain.rbegin(), chain.rend()};
}

ParentFrame ParentFrameOf(const Skeleton& skeleton, const MotionClip& clip, int frame, const std::vector<int>& chain) {
  ParentFrame frame_out;
  for (int a : chain) {
    frame_out.position += frame_out.rotation * frame_out.scale.cwiseProduct(clip.translation(frame, a));
    frame_out.rotation = frame_out.rotation * clip.rotation(frame, a);
    frame_out.scale = skeleton.joint(a).rest_scale;
  }
  return frame_out;
}

}  // namespace

int FindMotionRoot(const Skeleton& skeleton, std::span<const MotionClip* const> clips) {
  auto translates = [&](int j) {
    for (const MotionClip* clip : clips)
      if (j < static_cast<int>(clip->translation_animated.size()) && clip->translation_animated[j]) return true;
    return false;
  };
  // The pelvis: the first joint where the body branches (legs and spine). Its world motion
  // includes every ancestor, so a static or translating "joint_Root" above it is covered.
  int pelvis = -1;
  for (int j = 0; j < skeleton.num_joints() && pelvis < 0; ++j)
    if (skeleton.Children(j).size() >= 2) pelvis = j;
  if (pelvis >= 0) {
    std::vector<bool> above(skeleton.num_joints(), false);
    for (int a = pelvis; a != kNoParent; a = skeleton.parent(a)) above[a] = true;
    bool covered = true;
    for (int j = 0; j < skeleton.num_joints(); ++j) covered = covered && (above[j] || !translates(j));
    if (covered) return pelvis;
  }
  for (int j = 0; j < skeleton.num_joints(); ++j)
    if (translates(j)) return j;
  const std::vector<int> roots = skeleton.Roots();
  return roots.empty() ? -1 : roots.front();
}

TangentReference ComputeTangentReference(const Skeleton& skeleton, std::span<const MotionClip* const> clips,
                                         int root_joint) {
  return TangentReference{JointMeanRotations(skeleton, clips, root_joint), root_joint};
}

RootTrajectory ExtractRootTrajectory(const Skeleton& skeleton, const MotionClip& clip, int root_joint) {
  RootTrajectory out;
  out.heading_rad.resize(clip.num_frames);
  out.position_m.resize(clip.num_frames);
  out.tilt.resize(clip.num_frames);
  const Eigen::Vector3d scale = skeleton.parent(root_joint) == kNoParent
                                    ? Eigen::Vector3d::Ones()
                                    : skeleton.joint(skeleton.parent(root_joint)).rest_scale;
  const std::vector<int> chain = AncestorChain(skeleton, root_joint);
  for (int f = 0; f < clip.num_frames; ++f) {
    const ParentFrame parent = ParentFrameOf(skeleton, clip, f, chain);
    out.position_m[f] = parent.position + parent.rotation * scale.cwiseProduct(clip.translation(f, root_joint));
    double heading = 0.0;
    SplitHeading(parent.rotation * clip.rotation(f, root_joint), heading, out.tilt[f]);
    // Unwrap: keep consecutive headings less than pi apart.
    if (f > 0) heading = out.heading_rad[f - 1] + WrapToPi(heading - out.heading_rad[f - 1]);
    out.heading_rad[f] = heading;
  }
  return out;
}

Eigen::MatrixXd RootFeaturesFromTrajectory(const RootTrajectory& trajectory, double rate_hz) {
  const int frames = static_cast<int>(trajectory.position_m.size());
  Eigen::MatrixXd features = Eigen::MatrixXd::Zero(frames, kNumRootFeatures);
  for (int t = 0; t < frames; ++t) {
    features(t, kRootHeight) = trajectory.position_m[t].y();
    if (t + 1 >= frames) continue;
    Eigen::Vector3d step = trajectory.position_m[t + 1] - trajectory.position_m[t];
    step.y() = 0.0;
    const Eigen::Vector3d local = YawRotation(-trajectory.heading_rad[t]) * step;
    features(t, kRootForward) = local.z() * rate_hz;
    features(t, kRootLateral) = local.x() * rate_hz;
    features(t, kRootYawRate) = (trajectory.heading_rad[t + 1] - trajectory.heading_rad[t]) * rate_hz;
  }
  if (frames >= 2) {
    for (int c = kRootForward; c < kNumRootFeatures; ++c) features(frames - 1, c) = features(frames - 2, c);
  }
  return features;
}

RootTrajectory IntegrateRootFeatures(const Eigen::MatrixXd& features, double rate_hz, double start_heading_rad,
                                     const Eigen::Vector3d& start_position_m) {
  const int frames = static_cast<int>(features.rows());
  RootTrajectory out;
  out.heading_rad.resize(frames);
  out.position_m.resize(frames);
  if (frames == 0) return out;
  out.heading_rad[0] = start_heading_rad;
  out.position_m[0] = start_position_m;
  for (int t = 0; t + 1 < frames; ++t) {
    const Eigen::Vector3d local(features(t, kRootLateral) / rate_hz, 0.0, features(t, kRootForward) / rate_hz);
    out.position_m[t + 1] = out.position_m[t] + YawRotation(out.heading_rad[t]) * local;
    out.heading_rad[t + 1] = out.heading_rad[t] + features(t, kRootYawRate) / rate_hz;
  }
  for (int t = 0; t < frames; ++t) out.position_m[t].y() = features(t, kRootHeight);
  return out;
}

ClipSignals DecomposeClip(const Skeleton& skeleton, const MotionClip& clip, const TangentReference& reference) {
  ClipSignals out;
  const int joints = clip.num_joints;
  out.tangent.resize(clip.num_frames, 3 * joints);
  std::vector<Eigen::Quaterniond> inverse_means(joints);
  for (int j = 0; j < joints; ++j) inverse_means[j] = reference.joint_means[j].conjugate();
  for (int f = 0; f < clip.num_frames; ++f)
    for (int j = 0; j < joints; ++j)
      if (j != reference.root_joint)
        out.tangent.block<1, 3>(f, 3 * j) = LogMap(inverse_means[j] * clip.rotation(f, j)).transpose();
  if (reference.root_joint < 0) {
    out.root_features.resize(clip.num_frames, 0);
    return out;
  }
  const int root = reference.root_joint;
  const RootTrajectory trajectory = ExtractRootTrajectory(skeleton, clip, root);
  for (int f = 0; f < clip.num_frames; ++f)
    out.tangent.block<1, 3>(f, 3 * root) = LogMap(inverse_means[root] * trajectory.tilt[f]).transpose();
  out.root_features = RootFeaturesFromTrajectory(trajectory, clip.sample_rate_hz);
  out.start_heading_rad = trajectory.heading_rad.empty() ? 0.0 : trajectory.heading_rad[0];
  out.start_position_m = trajectory.position_m.empty() ? Eigen::Vector3d::Zero() : trajectory.position_m[0];
  return out;
}

Result<MotionClip> ComposeClip(const Skeleton& skeleton, const ClipSignals& signals,
                               const TangentReference& reference, const MotionClip& like) {
  const int joints = like.num_joints;
  if (signals.tangent.rows() != like.num_frames || signals.tangent.cols() != 3 * joints)
    return InvalidArgument("compose clip '" + like.name + "': tangent matrix is " +
                           std::to_string(signals.tangent.rows()) + " x " + std::to_string(signals.tangent.cols()) +
                           ", expected " + std::to_string(like.num_frames) + " x " + std::to_string(3 * joints));
  if (static_cast<int>(reference.joint_means.size()) != joints)
    return InvalidArgument("compose clip '" + like.name + "': reference has " +
                           std::to_string(reference.joint_means.size()) + " joint means, clip has " +
                           std::to_string(joints) + " joints");
  const int root = reference.root_joint;
  if (root >= 0 && (signals.root_features.rows() != like.num_frames || signals.root_features.cols() != kNumRootFeatures))
    return InvalidArgument("compose clip '" + like.name + "': root feature matrix has the wrong size");
  if (!signals.tangent.allFinite() || (root >= 0 && !signals.root_features.allFinite()))
    return NumericalFailure("compose clip '" + like.name + "': signals contain a non-finite value");

  MotionClip out = like;
  for (int f = 0; f < like.num_frames; ++f)
    for (int j = 0; j < joints; ++j)
      if (j != root)
        out.rotation(f, j) = (reference.joint_means[j] * ExpMap(signals.tangent.block<1, 3>(f, 3 * j).transpose())).normalized();
  if (root >= 0) {
    const RootTrajectory trajectory = IntegrateRootFeatures(signals.root_features, like.sample_rate_hz,
                                                            signals.start_heading_rad, signals.start_position_m);
    const Eigen::Vector3d scale =
        skeleton.parent(root) == kNoParent ? Eigen::Vector3d::Ones() : skeleton.joint(skeleton.parent(root)).rest_scale;
    const std::vector<int> chain = AncestorChain(skeleton, root);
    for (int f = 0; f < like.num_frames; ++f) {
      const Eigen::Quaterniond world = YawRotation(trajectory.heading_rad[f]) * reference.joint_means[root] *
                                       ExpMap(signals.tangent.block<1, 3>(f, 3 * root).transpose());
      const ParentFrame parent = ParentFrameOf(skeleton, out, f, chain);
      out.rotation(f, root) = (parent.rotation.conjugate() * world).normalized();
      out.translation(f, root) =
          (parent.rotation.conjugate() * (trajectory.position_m[f] - parent.position)).cwiseQuotient(scale);
    }
  }
  out.MakeContinuous();
  return out;
}

}  // namespace mocapfill
