// A rig's rest pose: the pose its joints' local frames are measured from when retargeting.
// Where a skin gives one, the bind pose (inverse bind matrices); else the skeleton's own
// rest (zero) pose; else the mean pose of a clip (or of a database); or the first frame of
// a clip. The automatic choice falls back to the mean pose when the zero pose is no standing
// pose at all (every Bandai-Namco bone points along +X when its rotations are zero): a
// capture's mean pose is much the same in every take and in the database built from them,
// while its first frame holds whatever step or turn the take begins with, and each bone's
// twist in the rest becomes its twist in the canonical T-pose.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <string_view>
#include <vector>

#include "processing/core/scene.h"
#include "processing/core/status.h"
#include "processing/retargeting/rig_mapping.h"

namespace mocapfill {

enum class RestSource { kAuto, kBind, kZero, kMean, kFirstFrame };

// "auto", "bind", "zero", "mean", "first-frame".
const char* RestSourceName(RestSource source);
Result<RestSource> ParseRestSource(std::string_view text);
// Every name ParseRestSource accepts, "auto" first (for option checks and help texts).
std::vector<std::string> RestSourceNames();

struct RigRest {
  std::vector<Eigen::Quaterniond> local_rotations;  // per joint
  std::vector<Eigen::Vector3d> local_translations;  // per joint, metres
  RestSource source = RestSource::kZero;            // which one was used (never kAuto)
  std::string reason;                               // why, for reports ("skin 'Geno' gives a bind pose")

  // World positions and rotations of this pose (forward kinematics).
  std::vector<Eigen::Vector3d> WorldPositions(const Skeleton& skeleton) const;
  std::vector<Eigen::Quaterniond> WorldRotations(const Skeleton& skeleton) const;
};

// The skeleton's zero pose: rest rotations and translations as the skeleton stores them.
RigRest ZeroPose(const Skeleton& skeleton);

// True when the pose stands: the mapped legs point down from the hips, the head is above the
// hips, and left and right limbs are apart. A pose that fails this cannot serve as a rest.
bool IsStandingPose(const Skeleton& skeleton, const RigMapping& mapping, const RigRest& pose);
// Why the pose does not stand ("the leftUpperLeg does not point down from the hips"), or ""
// when it does (IsStandingPose is this being empty).
std::string StandingProblem(const Skeleton& skeleton, const RigMapping& mapping, const RigRest& pose);

// A mean pose as a rest: every joint at its mean local rotation (`joint_means`, per joint, as
// JointMeanRotations gives them and the database stores them), except `root_joint` (-1:
// none), whose entry is its mean world tilt: the root stands upright at that tilt facing no
// particular way. Local translations are the skeleton's.
RigRest MeanPoseRest(const Skeleton& skeleton, const std::vector<Eigen::Quaterniond>& joint_means, int root_joint);

// Chooses the rest pose of `scene`'s skeleton. kBind needs a skin (joints outside every skin
// keep their zero-pose rotations, placed relative to the bound ones), kMean and kFirstFrame
// a clip (the first; kMean's root is the mapped hips); kAuto takes bind, else zero, else
// mean, else first frame (each only when it stands).
// Errors (kInvalidData): the source asked for is not available, or no candidate stands.
Result<RigRest> ChooseRest(const Scene& scene, const RigMapping& mapping, RestSource source);

}  // namespace mocapfill
