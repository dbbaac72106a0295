#include "processing/core/kinematics.h"

#include <algorithm>
#include <limits>

#include "processing/core/rotation.h"

namespace mocapfill {

Eigen::Vector3d RestOffset(const Skeleton& skeleton, int joint) {
  return skeleton.joint(skeleton.parent(joint)).rest_scale.cwiseProduct(skeleton.joint(joint).rest_translation);
}

void ComputeWorldPose(const Skeleton& skeleton, const MotionClip& clip, int frame, WorldPose& out) {
  const int n = skeleton.num_joints();
  out.positions.resize(n);
  out.rotations.resize(n);
  for (int j = 0; j < n; ++j) {
    const Eigen::Quaterniond& r = clip.rotation(frame, j);
    const Eigen::Vector3d& t = clip.translation(frame, j);
    const int p = skeleton.parent(j);
    if (p == kNoParent) {
      out.positions[j] = t;
      out.rotations[j] = r;
    } else {
      const Eigen::Vector3d scaled = skeleton.joint(p).rest_scale.cwiseProduct(t);
      out.positions[j] = out.positions[p] + out.rotations[p] * scaled;
      out.rotations[j] = out.rotations[p] * r;
    }
  }
}

std::vector<Eigen::Vector3d> ComputeWorldPositions(const Skeleton& skeleton, const MotionClip& clip) {
  std::vector<Eigen::Vector3d> result(static_cast<size_t>(clip.num_frames) * clip.num_joints);
  WorldPose pose;
  for (int f = 0; f < clip.num_frames; ++f) {
    ComputeWorldPose(skeleton, clip, f, pose);
    std::copy(pose.positions.begin(), pose.positions.end(), result.begin() + static_cast<size_t>(f) * clip.num_joints);
  }
  return result;
}

double RestPoseExtent(const Skeleton& skeleton, int axis) {
  MotionClip rest = MotionClip::RestPose(skeleton, 1, 30.0);
  WorldPose pose;
  ComputeWorldPose(skeleton, rest, 0, pose);
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    lo = std::min(lo, pose.positions[j][axis]);
    hi = std::max(hi, pose.positions[j][axis]);
    if (const auto& end = skeleton.joint(j).end_site) {
      const double v = (pose.positions[j] + pose.rotations[j] * *end)[axis];
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  }
  return skeleton.num_joints() ? hi - lo : 0.0;
}

std::vector<Eigen::Quaterniond> JointMeanRotations(const Skeleton& skeleton, std::span<const MotionClip* const> clips,
                                                   int root_joint) {
  const int joints = skeleton.num_joints();
  std::vector<Eigen::Quaterniond> means(joints, Eigen::Quaterniond::Identity());
  if (clips.empty()) return means;
  // Frame-major passes over all joints at once (the clip's memory order).
  std::vector<Eigen::Quaterniond> seeds(joints);
  for (int j = 0; j < joints; ++j) seeds[j] = clips.front()->rotation(0, j);
  for (int pass = 0; pass < 2; ++pass) {
    std::vector<Eigen::Vector4d> sums(joints, Eigen::Vector4d::Zero());
    for (const MotionClip* clip : clips)
      for (int f = 0; f < clip->num_frames; ++f)
        for (int j = 0; j < joints; ++j) AccumulateSignAligned(clip->rotation(f, j), seeds[j], sums[j]);
    for (int j = 0; j < joints; ++j) seeds[j] = NormalisedOrSeed(sums[j], seeds[j]);
  }
  for (int j = 0; j < joints; ++j) means[j] = seeds[j].normalized();
  if (root_joint < 0) return means;
  std::vector<int> chain;  // the root's ancestors, outermost first
  for (int p = skeleton.parent(root_joint); p != kNoParent; p = skeleton.parent(p)) chain.insert(chain.begin(), p);
  std::vector<Eigen::Quaterniond> tilts;
  for (const MotionClip* clip : clips)
    for (int f = 0; f < clip->num_frames; ++f) {
      Eigen::Quaterniond world = Eigen::Quaterniond::Identity();
      for (int a : chain) world = world * clip->rotation(f, a);
      double heading = 0.0;
      Eigen::Quaterniond tilt;
      SplitHeading(world * clip->rotation(f, root_joint), heading, tilt);
      tilts.push_back(tilt);
    }
  means[root_joint] = MeanRotation(tilts);
  return means;
}

}  // namespace mocapfill
