// A rig's rest pose: the pose its joints' local frames are measured from when retargeting.
// Where a skin gives one, the bind pose (inverse bind matrices); else the skeleton's own
// rest (zero) pose; or the first frame of a clip. The automatic choice falls back to the
// first frame when the zero pose is no standing pose at all (every Bandai-Namco bone points
// along +X when its rotations are zero).
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

enum class RestSource { kAuto, kBind, kZero, kFirstFrame };

// "auto", "bind", "zero", "first-frame".
const char* RestSourceName(RestSource source);
Result<RestSource> ParseRestSource(std::string_view text);

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

// Chooses the rest pose of `scene`'s skeleton. kBind needs a skin (joints outside every skin
// keep their zero-pose rotations, placed relative to the bound ones), kFirstFrame a clip;
// kAuto takes bind, else zero, else first frame (when zero is no standing pose).
// Errors (kInvalidData): the source asked for is not available, or no candidate stands.
Result<RigRest> ChooseRest(const Scene& scene, const RigMapping& mapping, RestSource source);

}  // namespace mocapfill
