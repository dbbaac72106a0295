// Retargeting: the motion of one humanoid rig put onto another (any naming, any rest pose),
// through the canonical humanoid.
#pragma once

#include <map>
#include <string>

#include "mocapfill/export.h"
#include "mocapfill/scene.h"

namespace mocapfill::api {

struct RigOptions {
  std::map<std::string, std::string> map;  // joint -> canonical bone (VRM name) overrides
  std::string rest = "auto";               // auto, bind, zero, mean, first-frame
};

// `motion`'s clips on `character`'s rig, in `character`'s scene (its meshes and skins kept).
// Throws Error (kInvalidInput) when either rig is not a humanoid the mapper can read.
MOCAPFILL_API Scene Retarget(const Scene& motion, const Scene& character, const RigOptions& motion_rig = {},
                             const RigOptions& character_rig = {});

}  // namespace mocapfill::api
