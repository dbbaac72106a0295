// Retargeting whole scenes: a rig read from a scene (mapped to the canonical humanoid, its
// rest pose chosen), and every clip of one scene put onto another scene's character, whose
// nodes, meshes and skins the result keeps.
#pragma once

#include <map>
#include <string>

#include "processing/core/scene.h"
#include "processing/core/status.h"
#include "processing/retargeting/rest_pose.h"
#include "processing/retargeting/retarget.h"
#include "processing/retargeting/rig_mapping.h"

namespace mocapfill {

struct RigOptions {
  std::map<std::string, std::string> map;  // joint -> canonical bone overrides
  RestSource rest = RestSource::kAuto;
};

struct PreparedRig {
  RigMapping mapping;
  HumanoidRig rig;
};

// Maps the scene's skeleton (confirming sides on its zero pose, or on its first frame when
// the zero pose does not stand) and chooses its rest pose. Errors as MapHumanoid, ChooseRest
// and HumanoidRig::Make.
Result<PreparedRig> PrepareRig(const Scene& scene, const RigOptions& options = {});

// `motion`'s clips on `character`'s rig, at their own rates, in `character`'s scene (its
// meshes and skins kept; its own clips replaced). Joints the canonical set does not cover
// stay at the character's rest. Two scenes of one rig (SameRig) share the motion's rest, so
// that the clips are copied exactly.
Result<Scene> RetargetScene(const Scene& motion, const Scene& character, const RigOptions& motion_rig = {},
                            const RigOptions& character_rig = {});

}  // namespace mocapfill
