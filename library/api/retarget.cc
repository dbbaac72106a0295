#include "mocapfill/retarget.h"

#include "library/api/access.h"
#include "processing/retargeting/retarget_scene.h"

namespace mocapfill::api {

namespace {

Result<mocapfill::RigOptions> ToRigOptions(const RigOptions& options, const std::string& which) {
  mocapfill::RigOptions out;
  out.map = options.map;
  Result<RestSource> rest = ParseRestSource(options.rest);
  if (!rest.ok()) return rest.status().WithContext(which + ".rest");
  out.rest = *rest;
  return out;
}

}  // namespace

Scene Retarget(const Scene& motion, const Scene& character, const RigOptions& motion_rig,
               const RigOptions& character_rig) {
  const mocapfill::RigOptions from = ValueOrThrow(ToRigOptions(motion_rig, "motion_rig"), FailureStage::kProcessing);
  const mocapfill::RigOptions onto = ValueOrThrow(ToRigOptions(character_rig, "character_rig"), FailureStage::kProcessing);
  return SceneAccess::Wrap(ValueOrThrow(
      RetargetScene(SceneAccess::Get(motion), SceneAccess::Get(character), from, onto), FailureStage::kInput));
}

}  // namespace mocapfill::api
