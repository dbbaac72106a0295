// The sketches an animator makes, as evaluation scenarios: which
// joints of the database's (Bandai-Namco) rig are keyed and how often. Each is scored like any
// sketch, with `mean` as its own baseline.
#pragma once

#include <string>
#include <vector>

#include "processing/core/status.h"
#include "processing/evaluation/sketch_maker.h"

namespace mocapfill {

struct SketchScenario {
  std::string name;
  std::string description;
  SketchSpec sketch;
};

// legs8 (hips and legs every 8 frames: the reference), legs4, legs16, upper-body (hips, torso,
// head and arms every 8; legs synthesised), root (hips only), root-arms (hips and both arms).
const std::vector<SketchScenario>& SketchScenarios();

// kInvalidArgument listing the known names when `name` is none of them.
Result<SketchScenario> FindSketchScenario(const std::string& name);

}  // namespace mocapfill
