// Units and axes, in one place: every importer converts to metres and Y-up here, so the
// rest pose, the animation and the inverse bind matrices are always converted together.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "processing/core/scene.h"
#include "processing/core/status.h"

namespace mocapfill {

// The length units mocapfill reads and writes, by name: "m", "cm", "mm", "in", "ft", "cmu"
// (CMU/cgspeed: 0.056444 m). Every option that takes a unit offers these, and "auto".
const std::vector<std::string>& UnitNames();
// "auto" and UnitNames(): the values of a --unit option.
std::vector<std::string> UnitChoices();
// UnitChoices() joined by ", ", for help texts.
std::string UnitChoicesText();

// Metres per unit for a name of UnitNames(), or nullopt.
std::optional<double> UnitScaleByName(const std::string& name);

struct UnitChoice {
  std::string name;
  double scale_to_m = 1.0;
  bool detected = false;
};

// Resolves the unit of a skeleton-only source. `requested` is ImportOptions::unit. With
// "auto", `default_name` is used unless the skeleton's height (`height_in_units`, rest
// pose extent along up) would be implausible for a human-sized figure (outside 0.5-3 m),
// in which case the named unit giving the height closest to 1.7 m is chosen.
Result<UnitChoice> ResolveUnit(const std::string& requested, const std::string& default_name,
                               double height_in_units);

// Multiplies every length of the scene (rest offsets, end sites, animated translations,
// mesh positions, inverse-bind translations) by `scale`.
void ScaleScene(Scene& scene, double scale);

// Rotates a Z-up scene to Y-up (a -90 degree turn about X) at the roots: root rest
// transforms, root animation, rigid meshes at the scene root, skinned mesh positions and
// inverse bind matrices. Children are unaffected, being expressed in their parents' frames.
void ConvertZUpToYUp(Scene& scene);

}  // namespace mocapfill
