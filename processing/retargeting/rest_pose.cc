#include "processing/retargeting/rest_pose.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "processing/core/kinematics.h"

namespace mocapfill {

namespace {

using B = HumanoidBone;

constexpr std::array<RestSource, 5> kRestSources = {RestSource::kAuto, RestSource::kBind, RestSource::kZero,
                                                    RestSource::kMean, RestSource::kFirstFrame};

struct WorldTransform {
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
};

std::vector<WorldTransform> Forward(const Skeleton& skeleton, const RigRest& pose) {
  std::vector<WorldTransform> world(skeleton.num_joints());
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const int p = skeleton.parent(j);
    if (p == kNoParent) {
      world[j].rotation = pose.local_rotations[j];
      world[j].translation = pose.local_translations[j];
    } else {
      const Eigen::Vector3d offset = skeleton.joint(p).rest_scale.cwiseProduct(pose.local_translations[j]);
      world[j].rotation = (world[p].rotation * pose.local_rotations[j]).normalized();
      world[j].translation = world[p].translation + world[p].rotation * offset;
    }
  }
  return world;
}

// The skin whose joints include the most mapped bones (none when no skin holds a bone).
int BestSkin(const Scene& scene, const RigMapping& mapping, int* covered_required, int* required_total) {
  int best = -1, best_count = 0;
  *covered_required = 0;
  *required_total = 0;
  for (size_t s = 0; s < scene.skins.size(); ++s) {
    int count = 0, required = 0, total = 0;
    for (int i = 0; i < kNumHumanoidBones; ++i) {
      const int j = mapping.joints[i];
      if (j < 0) continue;
      const bool in = std::find(scene.skins[s].joints.begin(), scene.skins[s].joints.end(), j) != scene.skins[s].joints.end();
      count += in;
      if (IsRequiredBone(BoneAt(i))) {
        ++total;
        required += in;
      }
    }
    if (count > best_count) {
      best = static_cast<int>(s);
      best_count = count;
      *covered_required = required;
      *required_total = total;
    }
  }
  return best;
}

// The bind pose of `skin`: the world transform of a skinned joint is the inverse of its
// inverse bind matrix; every other joint keeps its zero-pose local transform under its parent.
RigRest BindPose(const Scene& scene, const Skin& skin) {
  const Skeleton& skeleton = scene.skeleton;
  RigRest rest = ZeroPose(skeleton);
  std::vector<std::optional<Eigen::Matrix4d>> bind_world(skeleton.num_joints());
  for (size_t k = 0; k < skin.joints.size() && k < skin.inverse_bind_matrices.size(); ++k)
    bind_world[skin.joints[k]] = skin.inverse_bind_matrices[k].inverse();
  std::vector<WorldTransform> world(skeleton.num_joints());
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const int p = skeleton.parent(j);
    WorldTransform parent;
    if (p != kNoParent) parent = world[p];
    if (bind_world[j]) {
      // Columns of the bind matrix carry the joint's scale (about 1): normalise them away.
      Eigen::Matrix3d r = bind_world[j]->topLeftCorner<3, 3>();
      for (int c = 0; c < 3; ++c) r.col(c).normalize();
      world[j].rotation = Eigen::Quaterniond(r).normalized();
      world[j].translation = bind_world[j]->topRightCorner<3, 1>();
      const Eigen::Quaterniond inv_parent = parent.rotation.conjugate();
      rest.local_rotations[j] = (inv_parent * world[j].rotation).normalized();
      rest.local_translations[j] = inv_parent * (world[j].translation - parent.translation);
    } else {
      world[j].rotation = (parent.rotation * rest.local_rotations[j]).normalized();
      world[j].translation = parent.translation + parent.rotation * rest.local_translations[j];
    }
  }
  rest.source = RestSource::kBind;
  return rest;
}

// The mean pose of the scene's first clip, its root at the mapped hips.
RigRest ClipMeanPose(const Scene& scene, const RigMapping& mapping) {
  const int root = mapping.joint(HumanoidBone::kHips);
  const MotionClip* clip = &scene.clips.front();
  return MeanPoseRest(scene.skeleton, JointMeanRotations(scene.skeleton, {&clip, 1}, root), root);
}

RigRest FirstFrame(const Scene& scene) {
  const MotionClip& clip = scene.clips.front();
  RigRest rest;
  for (int j = 0; j < scene.skeleton.num_joints(); ++j) {
    rest.local_rotations.push_back(clip.rotation(0, j));
    rest.local_translations.push_back(clip.translation(0, j));
  }
  rest.source = RestSource::kFirstFrame;
  return rest;
}

}  // namespace

const char* RestSourceName(RestSource source) {
  switch (source) {
    case RestSource::kAuto: return "auto";
    case RestSource::kBind: return "bind";
    case RestSource::kZero: return "zero";
    case RestSource::kMean: return "mean";
    case RestSource::kFirstFrame: return "first-frame";
  }
  return "auto";
}

Result<RestSource> ParseRestSource(std::string_view text) {
  for (RestSource s : kRestSources)
    if (text == RestSourceName(s)) return s;
  return InvalidArgument("unknown rest pose '" + std::string(text) + "' (expected auto, bind, zero, mean or first-frame)");
}

std::vector<std::string> RestSourceNames() {
  std::vector<std::string> names;
  for (RestSource s : kRestSources) names.push_back(RestSourceName(s));
  return names;
}

std::vector<Eigen::Vector3d> RigRest::WorldPositions(const Skeleton& skeleton) const {
  std::vector<Eigen::Vector3d> out;
  for (const WorldTransform& t : Forward(skeleton, *this)) out.push_back(t.translation);
  return out;
}

std::vector<Eigen::Quaterniond> RigRest::WorldRotations(const Skeleton& skeleton) const {
  std::vector<Eigen::Quaterniond> out;
  for (const WorldTransform& t : Forward(skeleton, *this)) out.push_back(t.rotation);
  return out;
}

RigRest ZeroPose(const Skeleton& skeleton) {
  RigRest rest;
  for (const Joint& joint : skeleton.joints()) {
    rest.local_rotations.push_back(joint.rest_rotation);
    rest.local_translations.push_back(joint.rest_translation);
  }
  rest.source = RestSource::kZero;
  return rest;
}

RigRest MeanPoseRest(const Skeleton& skeleton, const std::vector<Eigen::Quaterniond>& joint_means, int root_joint) {
  RigRest rest = ZeroPose(skeleton);
  for (int j = 0; j < skeleton.num_joints(); ++j)
    if (j != root_joint) rest.local_rotations[j] = joint_means[j];
  if (root_joint >= 0) {
    Eigen::Quaterniond parent = Eigen::Quaterniond::Identity();
    for (int p = skeleton.parent(root_joint); p != kNoParent; p = skeleton.parent(p))
      parent = rest.local_rotations[p] * parent;
    rest.local_rotations[root_joint] = (parent.conjugate() * joint_means[root_joint]).normalized();
  }
  rest.source = RestSource::kMean;
  return rest;
}

bool IsStandingPose(const Skeleton& skeleton, const RigMapping& mapping, const RigRest& pose) {
  return StandingProblem(skeleton, mapping, pose).empty();
}

std::string StandingProblem(const Skeleton& skeleton, const RigMapping& m, const RigRest& pose) {
  const std::vector<Eigen::Vector3d> p = pose.WorldPositions(skeleton);
  const Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  for (auto [upper, lower] : {std::pair{B::kLeftUpperLeg, B::kLeftLowerLeg}, std::pair{B::kRightUpperLeg, B::kRightLowerLeg}}) {
    if (m.joint(upper) < 0 || m.joint(lower) < 0) continue;
    const Eigen::Vector3d thigh = p[m.joint(lower)] - p[m.joint(upper)];
    // A standing thigh points down: at most 60 degrees from straight down.
    if (thigh.norm() < 1e-9 || thigh.normalized().dot(up) > -0.5)
      return std::string("the ") + HumanoidBoneName(upper) + " does not point down from the hips";
  }
  if (m.has(B::kHead) && m.has(B::kHips)) {
    const Eigen::Vector3d trunk = p[m.joint(B::kHead)] - p[m.joint(B::kHips)];
    if (trunk.norm() < 1e-9 || trunk.normalized().dot(up) < 0.5) return "the head is not above the hips";
  }
  auto horizontal_gap = [&](B a, B b) {
    if (m.joint(a) < 0 || m.joint(b) < 0) return -1.0;
    Eigen::Vector3d d = p[m.joint(a)] - p[m.joint(b)];
    d -= d.dot(up) * up;
    return d.norm();
  };
  const double feet = horizontal_gap(B::kLeftFoot, B::kRightFoot);
  const double arms = horizontal_gap(B::kLeftUpperArm, B::kRightUpperArm);
  if (std::max(feet, arms) < 0.02) return "left and right limbs are not apart";
  return "";
}

Result<RigRest> ChooseRest(const Scene& scene, const RigMapping& mapping, RestSource source) {
  const Skeleton& skeleton = scene.skeleton;
  int covered = 0, required = 0;
  const int skin = BestSkin(scene, mapping, &covered, &required);
  const bool bind_usable = skin >= 0 && covered == required && required > 0;
  const std::string skin_name = skin >= 0 ? "skin '" + scene.skins[skin].name + "'" : "";
  if (source == RestSource::kBind) {
    if (skin < 0) return InvalidData("no skin holds the mapped bones: no bind pose (try --rest zero or first-frame)");
    RigRest rest = BindPose(scene, scene.skins[skin]);
    rest.reason = "asked for: " + skin_name + " gives a bind pose (" + std::to_string(covered) + " of " +
                  std::to_string(required) + " required bones skinned)";
    return rest;
  }
  if (source == RestSource::kFirstFrame) {
    if (scene.clips.empty() || scene.clips.front().num_frames == 0)
      return InvalidData("no clip: no first frame to take as the rest pose");
    RigRest rest = FirstFrame(scene);
    rest.reason = "asked for: frame 0 of clip '" + scene.clips.front().name + "'";
    return rest;
  }
  if (source == RestSource::kMean) {
    if (scene.clips.empty() || scene.clips.front().num_frames == 0)
      return InvalidData("no clip: no mean pose to take as the rest pose");
    RigRest rest = ClipMeanPose(scene, mapping);
    rest.reason = "asked for: the mean pose of clip '" + scene.clips.front().name + "'";
    return rest;
  }
  if (source == RestSource::kZero) {
    RigRest rest = ZeroPose(skeleton);
    rest.reason = "asked for: the skeleton's own rest (zero) pose";
    return rest;
  }
  if (bind_usable) {
    RigRest rest = BindPose(scene, scene.skins[skin]);
    rest.reason = skin_name + " covers every required bone: its bind pose is the rest";
    return rest;
  }
  RigRest zero = ZeroPose(skeleton);
  const std::string zero_problem = StandingProblem(skeleton, mapping, zero);
  if (zero_problem.empty()) {
    zero.reason = std::string(skin >= 0 ? skin_name + " misses required bones; " : "no skin; ") +
                  "the zero pose stands (legs down, head up)";
    return zero;
  }
  if (!scene.clips.empty() && scene.clips.front().num_frames > 0) {
    const std::string clip = "clip '" + scene.clips.front().name + "'";
    RigRest mean = ClipMeanPose(scene, mapping);
    const std::string mean_problem = StandingProblem(skeleton, mapping, mean);
    if (mean_problem.empty()) {
      mean.reason = "the zero pose is no standing pose (" + zero_problem + "): the mean pose of " + clip + " stands";
      return mean;
    }
    RigRest first = FirstFrame(scene);
    const std::string first_problem = StandingProblem(skeleton, mapping, first);
    if (first_problem.empty()) {
      first.reason = "neither the zero pose (" + zero_problem + ") nor the mean pose of " + clip + " (" +
                     mean_problem + ") stands: frame 0 of " + clip + " does";
      return first;
    }
    return InvalidData("no usable rest pose: no skin covers the required bones, the zero pose is no standing pose (" +
                       zero_problem + "), nor is the mean pose (" + mean_problem + ") or frame 0 (" + first_problem +
                       "); choose one with --rest bind|zero|mean|first-frame");
  }
  return InvalidData("no usable rest pose: no skin covers the required bones, no clip, and the zero pose is no standing pose (" +
                     zero_problem + "); choose one with --rest zero");
}

}  // namespace mocapfill
