// The fill operation's options as one schema: the pipeline's `fill` node takes them by name, and
// the `fill` and `eval` verbs get their flags generated from them (converter/node_flags.h), so
// names, defaults (those of FillOptions and SketchFillOptions), ranges and messages are written
// once. Where the command line spells an option its own way the spec says so (`flag`, and
// word pairs for switches: `--feet plant|free` is `plant_feet`).
#pragma once

#include <vector>

#include "processing/core/status.h"
#include "processing/fill/fill_options.h"
#include "processing/graph/node.h"
#include "processing/sketch_fill/sketch_fill.h"

namespace mocapfill::graph {

// The fill methods' options (FillOptions): method, joining, texture, matching, coverage, and
// the pca/hybrid fit and edits.
std::vector<OptionSpec> FillMethodOptionSpecs();

// The sketch's options (rig map, rest pose, output rate, keep/synthesize, position keys,
// planted feet), then FillMethodOptionSpecs().
std::vector<OptionSpec> SketchFillOptionSpecs();

// Options checked against those schemas (CheckNodeOptions) as the fill takes them. Errors
// (kInvalidArgument) for what only the whole set can tell (FillOptions::Validate; a dial key
// that is no component number), naming the option by `label` (default `option "name"`).
Result<FillOptions> FillOptionsFrom(const NodeOptions& options,
                                    const std::function<std::string(const std::string&)>& label = {});
Result<SketchFillOptions> SketchFillOptionsFrom(const NodeOptions& options,
                                                const std::function<std::string(const std::string&)>& label = {});

}  // namespace mocapfill::graph
