#include "processing/retargeting/retarget_scene.h"

namespace mocapfill {

Result<PreparedRig> PrepareRig(const Scene& scene, const RigOptions& options) {
  const Skeleton& s = scene.skeleton;
  RigMapOptions map_options;
  map_options.overrides = options.map;
  std::vector<Eigen::Vector3d> pose = ZeroPose(s).WorldPositions(s);
  Result<RigMapping> mapping = MapHumanoid(s, pose, map_options);
  if (!mapping.ok()) return mapping.status();
  ASSIGN_OR_RETURN(const RigRest rest, ChooseRest(scene, *mapping, options.rest));
  if (rest.source != RestSource::kZero) {
    // Sides are confirmed again on the pose the rig will be read in.
    ASSIGN_OR_RETURN(RigMapping confirmed, MapHumanoid(s, rest.WorldPositions(s), map_options));
    mapping = std::move(confirmed);
  }
  ASSIGN_OR_RETURN(HumanoidRig rig, HumanoidRig::Make(s, *mapping, rest));
  return PreparedRig{*mapping, std::move(rig)};
}

Result<Scene> RetargetScene(const Scene& motion, const Scene& character, const RigOptions& motion_rig,
                            const RigOptions& character_rig) {
  if (motion.clips.empty()) return InvalidData("the motion has no animation to retarget");
  Result<PreparedRig> from = PrepareRig(motion, motion_rig);
  if (!from.ok()) return from.status().WithContext("motion rig");
  Scene out = character;
  out.clips.clear();
  if (SameRig(motion.skeleton, character.skeleton, motion.clips.front().translation_animated) &&
      character_rig.rest == RestSource::kAuto) {
    for (const MotionClip& clip : motion.clips) out.clips.push_back(clip);
    return out;
  }
  Result<PreparedRig> to = PrepareRig(character, character_rig);
  if (!to.ok()) return to.status().WithContext("target rig");
  for (const MotionClip& clip : motion.clips) out.clips.push_back(RetargetClip(from->rig, clip, to->rig));
  return out;
}

}  // namespace mocapfill
