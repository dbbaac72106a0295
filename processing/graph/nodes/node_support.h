// Helpers shared by the node adapters: option specifications in one line each, and the
// motion-port conventions (a motion's first clip is the one processed; outputs keep the
// input's asset).
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "processing/core/scene.h"
#include "processing/core/status.h"
#include "processing/graph/node.h"

namespace mocapfill::graph {

OptionSpec BoolOption(std::string name, bool default_value, std::string doc);
OptionSpec IntOption(std::string name, int default_value, std::optional<double> min, std::optional<double> max,
                     std::string doc, std::string unit = "");
// min_exclusive: the bound itself is rejected (a rate or tolerance must be > 0).
OptionSpec NumberOption(std::string name, double default_value, std::optional<double> min, bool min_exclusive,
                        std::optional<double> max, std::string unit, std::string doc);
OptionSpec StringOption(std::string name, std::string default_value, std::vector<std::string> choices, std::string doc);
// An empty list as default.
OptionSpec ListOption(std::string name, OptionType type, std::string doc);
// `spec` spelled `--flag` on the command line (OptionSpec::flag).
OptionSpec WithFlag(OptionSpec spec, std::string flag);
// `spec`, a kBool, set on the command line by a word pair (`--texture on|off`).
OptionSpec WithWords(OptionSpec spec, std::string yes, std::string no);
// `spec` with an extra check (OptionSpec::check).
OptionSpec WithCheck(OptionSpec spec, std::function<Status(const OptionValue&)> check);
// `spec` with inclusive bounds (for lists: on every element).
OptionSpec WithBounds(OptionSpec spec, double min, double max);

// The scene's first clip, or kInvalidData "<port>: no animation" / "... has no frames".
Result<const MotionClip*> FirstClip(const Scene& scene, const std::string& port);

// `scene` with its clips replaced by `clip` (skeleton, meshes and skins kept).
Value WithClip(const Scene& scene, MotionClip clip);

// `clip` at `rate_hz` (unchanged when the rates agree to 1e-9 relative).
Result<MotionClip> AtRate(const MotionClip& clip, double rate_hz);

// kInvalidData unless both skeletons name the same joints in the same order.
Status CheckSameJoints(const Skeleton& a, const Skeleton& b, const std::string& a_port, const std::string& b_port);

}  // namespace mocapfill::graph
