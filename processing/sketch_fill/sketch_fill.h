// The fill use case, as the `fill` verb and the pipeline's `fill` node run it: a sketch on
// the user's own rig and at the user's own key times is mapped to the canonical humanoid,
// retargeted onto the database's rig, filled there at the database rate, retargeted back,
// sampled at the sketch's rate (plus any key time off that grid), and its keys pinned so
// that the output reproduces every key at the animator's exact key time. The sketch's scene
// (nodes, meshes, skins) is kept; only its animation is replaced.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/core/pca_model.h"
#include "processing/core/scene.h"
#include "processing/core/status.h"
#include "processing/core/motion_database.h"
#include "processing/fill/fill_options.h"
#include "processing/fill/fill_report.h"
#include "processing/motion/foot_plant.h"
#include "processing/retargeting/rest_pose.h"

namespace mocapfill {

struct SketchFillOptions {
  FillOptions fill;
  // Rig map overrides: sketch joint -> canonical bone (VRM name) or database joint name.
  std::map<std::string, std::string> map;
  RestSource rest = RestSource::kAuto;  // the sketch rig's rest pose
  // Output rate (Hz); 0 = the sketch's own (as detected from its key times on import).
  double output_rate_hz = 0.0;
  std::vector<std::string> keep;        // only these joints stay keyed
  std::vector<std::string> synthesize;  // joints synthesised even when keyed
  // Joints whose translation keys are world-space position targets (hybrid method only).
  std::vector<std::string> position_keys;
  // Hold feet that stand at two consecutive keys between them (foot_plant.h): `--feet plant`.
  bool plant_feet = true;
  FootPlantOptions feet;
};

// How the sketch's rig was read, for reports.
struct RigSummary {
  std::string family;
  std::string rest;         // rest source name and reason
  bool same_as_database = false;
  int mapped_bones = 0;
  std::vector<std::string> warnings;
};

struct KeyCheck {
  std::string joint;
  int keys = 0;
  double mean_deg = 0.0;
  double max_deg = 0.0;
};

struct SketchFillResult {
  Scene scene;                  // the sketch's scene with the filled clip
  MotionClip keyed_sketch;      // the sketch's clip as filled: keys after keep/synthesize
  FillReport report;            // of the fill on the database rig (its key errors replaced below)
  RigSummary rig;
  double output_rate_hz = 0.0;
  bool uniform = true;          // false when key times off the rate's grid were added as samples
  double database_rate_hz = 0.0;
  // Per sketch joint: "keyed" / "textured" (keys kept; textured adds captured detail),
  // "synthesized" (from the database), "kept" (outside the canonical humanoid: the sketch's
  // own values); keys and their errors at the exact key times.
  std::vector<JointFillInfo> joints;
  std::vector<KeyCheck> key_checks;  // per keyed sketch joint, at its exact key times
  double key_error_mean_deg = 0.0;
  double key_error_max_deg = 0.0;
  double translation_key_error_max_m = 0.0;
  double position_key_error_max_m = 0.0;  // --position-keys targets against the output's joints
  double max_frame_jump_deg = 0.0;  // largest rotation change of any joint between output frames
  FootPlantReport feet;             // the contacts held (empty with plant_feet off)
  std::vector<std::string> warnings;
};

// Errors: kInvalidArgument for bad options (unknown joints in keep/synthesize/position_keys);
// kInvalidData for a sketch without animation or keys, a rig that is not humanoid, a bad map,
// translation keys on a non-root joint that would stretch a bone (unless listed in
// position_keys); the fill's own errors.
Result<SketchFillResult> FillSketch(const Scene& sketch, const MotionDatabase& db, const SketchFillOptions& options,
                                    const PcaModel* model = nullptr);

// Rotation key errors of `written` (e.g. read back from the file the fill wrote; joints
// matched by name) against the sketch's keys at their exact times. The written clip is
// evaluated through its own exact samples where it has them (a file read back keeps them),
// as a player would interpolate the file.
std::vector<KeyCheck> CheckKeys(const Skeleton& written_skeleton, const MotionClip& written,
                                const Skeleton& sketch_skeleton, const MotionClip& sketch);

// Makes `checks` the result's key errors: the per-joint figures, the totals and the report's.
void ApplyKeyChecks(std::vector<KeyCheck> checks, SketchFillResult& result);

}  // namespace mocapfill
