// Node types of the processing graph: typed ports, option specifications with
// defaults, units and ranges, and the Node interface a validated node runs through. The graph
// core knows nothing of files or JSON: nodes that read or write files are registered by the
// use cases (library/pipeline/), algorithm nodes by processing/graph/processing_nodes.h.
#pragma once

#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/core/pca_model.h"
#include "processing/core/scene.h"
#include "processing/core/status.h"
#include "processing/graph/option_value.h"

namespace mocapfill {
struct SketchFillResult;  // processing/sketch_fill/sketch_fill.h
}  // namespace mocapfill

namespace mocapfill::graph {

// What flows along an edge. A motion is a Scene (skeleton, clips, meshes and skins kept so
// an exported result still carries the sketch's asset).
enum class PortType { kMotion, kDatabase, kPcaModel };
const char* PortTypeName(PortType type);  // "motion", "database", "pca_model"

using Value = std::variant<std::shared_ptr<const Scene>, std::shared_ptr<const MotionDatabase>,
                           std::shared_ptr<const PcaModel>>;
PortType TypeOf(const Value& value);

struct PortSpec {
  std::string name;
  PortType type = PortType::kMotion;
  bool optional = false;
  std::string doc;
};

enum class OptionType {
  kBool,
  kInt,          // a JSON number without fraction
  kNumber,
  kString,       // free text, or one of `choices` when that list is not empty
  kPath,         // a file or folder; relative paths resolve against the pipeline's folder
  kNumberList,   // [0.5, 1, 2]
  kStringList,   // ["Hips", "Spine"]
  kNumberMap,    // {"1": 2.0}: numbers by name
  kStringMap,    // {"Hip": "Hips"}: strings by name
};
const char* OptionTypeName(OptionType type);  // "bool", "int", "number", ...

struct OptionSpec {
  std::string name;
  OptionType type = OptionType::kString;
  OptionValue default_value;   // kNull: no default (see `required`)
  bool required = false;
  std::string unit;            // "Hz", "deg", "s", ... (documentation; the name carries it too)
  std::optional<double> min;   // kInt/kNumber (and list/map elements): inclusive bounds
  std::optional<double> max;
  bool min_exclusive = false;  // min itself is not allowed (e.g. a rate > 0)
  // kString: the allowed values. kPath: words that are not paths (e.g. "default").
  std::vector<std::string> choices;
  // Extra check after the type and range checks (e.g. ParseFillMethod, so new fill methods
  // appear without touching the graph). Its message follows `option "name": `.
  std::function<Status(const OptionValue&)> check;
  std::string doc;
  // The command line's spelling when it is not the name's with '-' for '_' (the fill's
  // "fragment_band_hz" is `--fragment-hz`), so a verb keeps its flags when its options
  // come from a node's schema.
  std::string flag;
  // kBool on the command line as a word for true and one for false (`--feet plant|free`);
  // empty: a switch (`--periodic`, `--periodic=false`).
  std::vector<std::string> words;
};

// Checks `value` against `spec` (type, range, choices, `check`): kInvalidArgument with a
// message such as `expected a number >= 1, got 0` (no node or option prefix).
Status CheckOption(const OptionSpec& spec, const OptionValue& value);

// An option's value written as text, as the command line and the API's option maps give it:
// numbers ("+1.5" too), "true"/"on"/"1" and "false"/"off"/"0" (and the spec's `words`) for
// booleans, comma-separated lists, "key=value,..." maps. Text that is not of the option's type
// stays a string for CheckOption to refuse with its message; a map item without '=' is
// refused here (kInvalidArgument starting with `label`).
Result<OptionValue> OptionValueFromText(const OptionSpec& spec, const std::string& text, const std::string& label);

// The options of one node after validation: every spec'd option with its given or default
// value. Getters must only be called with names of the node type's specs.
class NodeOptions {
 public:
  NodeOptions() = default;
  explicit NodeOptions(std::map<std::string, OptionValue> values) : values_(std::move(values)) {}

  bool Has(const std::string& name) const;  // given or defaulted (not null)
  const OptionValue& Get(const std::string& name) const;
  bool Bool(const std::string& name) const { return Get(name).boolean; }
  int Int(const std::string& name) const { return static_cast<int>(Get(name).number); }
  double Number(const std::string& name) const { return Get(name).number; }
  const std::string& String(const std::string& name) const { return Get(name).text; }
  std::vector<double> NumberList(const std::string& name) const;
  std::vector<std::string> StringList(const std::string& name) const;
  std::map<std::string, double> NumberMap(const std::string& name) const;
  std::map<std::string, std::string> StringMap(const std::string& name) const;
  const std::map<std::string, OptionValue>& values() const { return values_; }

 private:
  std::map<std::string, OptionValue> values_;
};

// The inputs of one run: a value per connected port.
class NodeInputs {
 public:
  void Set(const std::string& port, Value value) { values_[port] = std::move(value); }
  bool Has(const std::string& port) const { return values_.count(port) > 0; }
  // The typed value of a connected port (types were checked when the graph was built).
  const Scene& Motion(const std::string& port) const;
  const MotionDatabase& Database(const std::string& port) const;
  const PcaModel& Model(const std::string& port) const;

 private:
  std::map<std::string, Value> values_;
};

// Warnings a node reports (the CLI prints them; library code never prints).
struct RunContext {
  std::vector<std::string> warnings;
  // A fill node's whole result (joints, key errors, fragments, coverage), for run reports.
  std::shared_ptr<const SketchFillResult> fill;
};

// A configured node: immutable once built from validated options; Run is deterministic.
class Node {
 public:
  virtual ~Node() = default;
  // The output value (for a node type without output, any value; it is dropped).
  virtual Result<Value> Run(const NodeInputs& inputs, RunContext& context) const = 0;
};

// A node's options checked against its type's schema, defaults added: what a pipeline file's
// node and a command-line verb generated from the same schema (converter/node_flags.h) both
// go through. `given` in the order given; every problem is reported, one per line, each
// starting with `label(option name)` (default: `option "name"`). kInvalidArgument.
struct NodeTypeSpec;
Result<NodeOptions> CheckNodeOptions(const NodeTypeSpec& spec,
                                     const std::vector<std::pair<std::string, OptionValue>>& given,
                                     const std::function<std::string(const std::string&)>& label = {});

// Where a node's failures belong, so the CLI can map I/O errors to input or output exit codes.
enum class NodeRole { kSource, kProcess, kSink };

using NodeFactory = std::function<Result<std::unique_ptr<Node>>(const NodeOptions& options)>;

struct NodeTypeSpec {
  std::string type;                  // "fill"
  std::string summary;               // one line for --list-nodes and the docs
  NodeRole role = NodeRole::kProcess;
  std::vector<PortSpec> inputs;
  std::optional<PortSpec> output;    // at most one output; none for sinks (export)
  std::vector<OptionSpec> options;
  // Builds the node from checked options; may check combinations of options (messages name
  // the option). Called while the graph is validated, before any node runs.
  NodeFactory create;
};

}  // namespace mocapfill::graph
