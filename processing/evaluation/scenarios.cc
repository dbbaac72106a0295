#include "processing/evaluation/scenarios.h"

namespace mocapfill {

namespace {

SketchScenario Make(std::string name, std::string description, std::vector<std::string> keep, int every) {
  SketchScenario s{std::move(name), std::move(description), {}};
  s.sketch.keep_joints = std::move(keep);
  s.sketch.key_every_frames = every;
  return s;
}

}  // namespace

const std::vector<SketchScenario>& SketchScenarios() {
  static const std::vector<SketchScenario> scenarios = [] {
    const std::vector<std::string> legs = {"Hips",       "UpperLeg_L", "LowerLeg_L", "Foot_L", "Toes_L",
                                           "UpperLeg_R", "LowerLeg_R", "Foot_R",     "Toes_R"};
    const std::vector<std::string> upper = {"Hips",       "Spine",      "Chest",      "Neck",       "Head",
                                            "Shoulder_L", "UpperArm_L", "LowerArm_L", "Hand_L",     "Shoulder_R",
                                            "UpperArm_R", "LowerArm_R", "Hand_R"};
    const std::vector<std::string> arms = {"Hips",       "Shoulder_L", "UpperArm_L", "LowerArm_L", "Hand_L",
                                           "Shoulder_R", "UpperArm_R", "LowerArm_R", "Hand_R"};
    return std::vector<SketchScenario>{
        Make("legs8", "hips and legs keyed every 8 frames", legs, 8),
        Make("legs4", "hips and legs keyed every 4 frames", legs, 4),
        Make("legs16", "hips and legs keyed every 16 frames", legs, 16),
        Make("upper-body", "hips, torso, head and arms keyed every 8 frames; legs synthesised", upper, 8),
        Make("root", "hips only, every 8 frames", {"Hips"}, 8),
        Make("root-arms", "hips and both arms keyed every 8 frames; torso, head and legs synthesised", arms, 8),
    };
  }();
  return scenarios;
}

Result<SketchScenario> FindSketchScenario(const std::string& name) {
  std::string known;
  for (const SketchScenario& s : SketchScenarios()) {
    if (s.name == name) return s;
    known += (known.empty() ? "" : ", ") + s.name;
  }
  return InvalidArgument("unknown scenario '" + name + "' (known: " + known + ")");
}

}  // namespace mocapfill
