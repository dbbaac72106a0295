// The processing graph: nodes described as plain data (GraphConfig, filled from a
// pipeline file by library/pipeline), validated as a whole before anything runs (types,
// options, ports, cycles), ordered topologically and run one node after another.
//
// Every validation message names the node, its type and the option or input at fault:
//   node "fill" (fill): option "method": unknown method 'foo' (expected ...)
//   node "out" (export): input "motion": no node "fil" in the pipeline
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "processing/graph/node.h"
#include "processing/graph/node_registry.h"

namespace mocapfill::graph {

constexpr int kGraphVersion = 1;

struct NodeConfig {
  std::string id;    // unique; letters, digits, '_' and '-'
  std::string type;  // a registered node type
  std::vector<std::pair<std::string, std::string>> inputs;  // port name -> producing node id
  std::vector<std::pair<std::string, OptionValue>> options;  // as given (defaults are added)
};

struct GraphConfig {
  int version = kGraphVersion;
  std::vector<NodeConfig> nodes;
};

// One node of a validated graph, in run order.
struct PlannedNode {
  std::string id;
  const NodeTypeSpec* spec = nullptr;
  NodeOptions options;                              // every option, given or default
  std::vector<std::pair<std::string, int>> inputs;  // port -> index (in run order) of its producer
  std::shared_ptr<const Node> node;
};

struct NodeRun {
  std::string id;
  std::string type;
  double seconds = 0.0;
  std::vector<std::string> warnings;
  std::shared_ptr<const SketchFillResult> fill;  // a fill node's result (RunContext::fill)
};

struct GraphRun {
  Status status;             // the first failure, prefixed with its node
  int failed_node = -1;      // index in run order of the failing node, or -1
  std::vector<NodeRun> nodes;  // the nodes that ran (the failing one last)
  double total_seconds = 0.0;
};

// "node \"fill\" (fill)": how messages name a node.
std::string NodeLabel(const std::string& id, const std::string& type);

class Graph {
 public:
  // Validates the whole configuration against the registry and builds every node (their
  // factories check option combinations). All problems found are reported, one per line of
  // the returned kInvalidArgument message; nothing runs.
  static Result<Graph> Build(const GraphConfig& config, const NodeRegistry& registry);

  const std::vector<PlannedNode>& plan() const { return plan_; }

  // Runs the nodes in order (sinks after every other node); stops at the first failure. A value is released once its last
  // consumer has run. `on_node_done` (optional) is called after each node that succeeded.
  GraphRun Run(const std::function<void(const PlannedNode&)>& on_node_done = {}) const;

 private:
  std::vector<PlannedNode> plan_;
  std::vector<int> last_use_;  // per node: index of its last consumer, or -1
};

}  // namespace mocapfill::graph
