#include "processing/graph/graph.h"

#include <cctype>
#include <chrono>
#include <map>
#include <optional>
#include <set>
#include <sstream>

namespace mocapfill::graph {

std::string NodeLabel(const std::string& id, const std::string& type) {
  return "node \"" + id + "\" (" + type + ")";
}

namespace {

// Collects every problem of a configuration, each line naming its node.
class Problems {
 public:
  void Add(const NodeConfig& node, const std::string& what) {
    lines_.push_back(NodeLabel(node.id, node.type.empty() ? "?" : node.type) + ": " + what);
  }
  void AddGlobal(const std::string& what) { lines_.push_back(what); }
  bool empty() const { return lines_.empty(); }
  Status ToStatus() const {
    std::string message;
    for (size_t i = 0; i < lines_.size(); ++i) message += (i ? "\n" : "") + lines_[i];
    return InvalidArgument(message);
  }

 private:
  std::vector<std::string> lines_;
};

bool ValidId(const std::string& id) {
  if (id.empty()) return false;
  for (char c : id)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') return false;
  return true;
}

std::string NameList(const std::vector<std::string>& names) {
  std::string out;
  for (size_t i = 0; i < names.size(); ++i) out += (i ? ", " : "") + names[i];
  return out;
}

// Given options checked against the specs, plus defaults; false when any was wrong.
bool CheckOptions(const NodeConfig& node, const NodeTypeSpec& spec, Problems& problems, NodeOptions& out) {
  Result<NodeOptions> checked = CheckNodeOptions(spec, node.options);
  if (checked.ok()) {
    out = std::move(checked).value();
    return true;
  }
  std::istringstream lines(checked.status().message());
  for (std::string line; std::getline(lines, line);) problems.Add(node, line);
  return false;
}

struct Checked {
  const NodeTypeSpec* spec = nullptr;
  bool ok = false;
  NodeOptions options;
  std::vector<std::pair<std::string, int>> inputs;  // port -> config index of the producer
};

void CheckInputs(const GraphConfig& config, size_t index, const std::map<std::string, size_t>& by_id,
                 const std::vector<Checked>& checked, Problems& problems, Checked& out) {
  const NodeConfig& node = config.nodes[index];
  const NodeTypeSpec& spec = *out.spec;
  std::vector<std::string> ports;
  for (const PortSpec& port : spec.inputs) ports.push_back(port.name);
  std::set<std::string> given;
  for (const auto& [port_name, producer] : node.inputs) {
    const std::string where = "input \"" + port_name + "\": ";
    const PortSpec* port = nullptr;
    for (const PortSpec& p : spec.inputs)
      if (p.name == port_name) port = &p;
    if (!port) {
      problems.Add(node, where + "unknown port (" + spec.type + " has: " +
                             (ports.empty() ? std::string("no inputs") : NameList(ports)) + ")");
      out.ok = false;
      continue;
    }
    if (!given.insert(port_name).second) {
      problems.Add(node, where + "given twice");
      out.ok = false;
      continue;
    }
    const auto it = by_id.find(producer);
    if (it == by_id.end()) {
      problems.Add(node, where + "no node \"" + producer + "\" in the pipeline");
      out.ok = false;
      continue;
    }
    const Checked& source = checked[it->second];
    if (!source.spec) continue;  // its unknown type is reported on its own
    const std::string source_label = NodeLabel(producer, source.spec->type);
    if (!source.spec->output) {
      problems.Add(node, where + source_label + " has no output");
      out.ok = false;
    } else if (source.spec->output->type != port->type) {
      problems.Add(node, where + "expects a " + PortTypeName(port->type) + ", " + source_label + " gives a " +
                             PortTypeName(source.spec->output->type));
      out.ok = false;
    } else {
      out.inputs.emplace_back(port_name, static_cast<int>(it->second));
    }
  }
  for (const PortSpec& port : spec.inputs) {
    if (port.optional || given.count(port.name)) continue;
    problems.Add(node, "input \"" + port.name + "\": missing (a " + std::string(PortTypeName(port.type)) +
                           " is required: " + port.doc + ")");
    out.ok = false;
  }
}

// Kahn's algorithm, taking ready nodes in file order so the plan reads like the file.
std::vector<size_t> TopologicalOrder(const GraphConfig& config, const std::vector<Checked>& checked,
                                     std::vector<size_t>& in_cycle) {
  const size_t n = config.nodes.size();
  std::vector<int> pending(n, 0);
  std::vector<std::vector<size_t>> consumers(n);
  for (size_t i = 0; i < n; ++i)
    for (const auto& [port, producer] : checked[i].inputs) {
      ++pending[i];
      consumers[producer].push_back(i);
    }
  std::vector<size_t> order;
  std::vector<bool> done(n, false);
  const auto is_sink = [&](size_t i) { return checked[i].spec && checked[i].spec->role == NodeRole::kSink; };
  for (bool progress = true; progress;) {
    progress = false;
    // Sinks wait until nothing else is ready: every export runs after all processing, so a
    // failing node leaves no output behind.
    for (bool sinks : {false, true}) {
      for (size_t i = 0; i < n && !progress; ++i) {
        if (done[i] || pending[i] > 0 || is_sink(i) != sinks) continue;
        done[i] = true;
        progress = true;
        order.push_back(i);
        for (size_t c : consumers[i]) --pending[c];
      }
      if (progress) break;  // restart from the first node: file order among the ready ones
    }
  }
  for (size_t i = 0; i < n; ++i)
    if (!done[i]) in_cycle.push_back(i);
  return order;
}

// True when node `start` feeds itself through its inputs' producers.
bool OnCycle(const std::vector<Checked>& checked, size_t start) {
  std::vector<bool> seen(checked.size(), false);
  std::vector<size_t> stack;
  for (const auto& [port, producer] : checked[start].inputs) stack.push_back(static_cast<size_t>(producer));
  while (!stack.empty()) {
    const size_t node = stack.back();
    stack.pop_back();
    if (node == start) return true;
    if (seen[node]) continue;
    seen[node] = true;
    for (const auto& [port, producer] : checked[node].inputs) stack.push_back(static_cast<size_t>(producer));
  }
  return false;
}

}  // namespace

Result<Graph> Graph::Build(const GraphConfig& config, const NodeRegistry& registry) {
  Problems problems;
  if (config.version != kGraphVersion)
    problems.AddGlobal("\"version\": expected " + std::to_string(kGraphVersion) + ", got " + std::to_string(config.version));
  if (config.nodes.empty()) problems.AddGlobal("\"nodes\": the pipeline has no node");
  std::map<std::string, size_t> by_id;
  std::vector<Checked> checked(config.nodes.size());
  for (size_t i = 0; i < config.nodes.size(); ++i) {
    const NodeConfig& node = config.nodes[i];
    if (!ValidId(node.id)) problems.Add(node, "\"id\": expected letters, digits, '_' or '-'");
    if (!by_id.emplace(node.id, i).second) problems.Add(node, "\"id\": duplicate id (another node is named so)");
    checked[i].spec = registry.Find(node.type);
    if (!checked[i].spec) {
      problems.Add(node, "unknown node type \"" + node.type + "\" (known: " + NameList(registry.Types()) + ")");
      continue;
    }
    checked[i].ok = CheckOptions(node, *checked[i].spec, problems, checked[i].options);
  }
  for (size_t i = 0; i < config.nodes.size(); ++i)
    if (checked[i].spec) CheckInputs(config, i, by_id, checked, problems, checked[i]);
  std::vector<size_t> in_cycle;
  const std::vector<size_t> order = TopologicalOrder(config, checked, in_cycle);
  for (size_t i : in_cycle)
    problems.Add(config.nodes[i], OnCycle(checked, i) ? "is part of a cycle (its inputs depend on its own output)"
                                                      : "depends on a cycle (one of its inputs is fed by one)");

  Graph graph;
  std::vector<int> position(config.nodes.size(), -1);
  for (size_t i : order) {
    const NodeConfig& node = config.nodes[i];
    PlannedNode planned{node.id, checked[i].spec, checked[i].options, {}, nullptr};
    if (checked[i].spec && checked[i].ok) {
      Result<std::unique_ptr<Node>> created = checked[i].spec->create(checked[i].options);
      if (!created.ok()) problems.Add(node, created.status().message());
      else planned.node = std::move(created).value();
    }
    for (const auto& [port, producer] : checked[i].inputs) planned.inputs.emplace_back(port, position[producer]);
    position[i] = static_cast<int>(graph.plan_.size());
    graph.plan_.push_back(std::move(planned));
  }
  if (!problems.empty()) return problems.ToStatus();
  graph.last_use_.assign(graph.plan_.size(), -1);
  for (size_t i = 0; i < graph.plan_.size(); ++i)
    for (const auto& [port, producer] : graph.plan_[i].inputs) graph.last_use_[producer] = static_cast<int>(i);
  return graph;
}

GraphRun Graph::Run(const std::function<void(const PlannedNode&)>& on_node_done) const {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  GraphRun run;
  std::vector<std::optional<Value>> values(plan_.size());
  for (size_t i = 0; i < plan_.size(); ++i) {
    const PlannedNode& planned = plan_[i];
    NodeInputs inputs;
    for (const auto& [port, producer] : planned.inputs) inputs.Set(port, *values[producer]);
    RunContext context;
    const auto node_start = Clock::now();
    Result<Value> output = planned.node->Run(inputs, context);
    run.nodes.push_back({planned.id, planned.spec->type, std::chrono::duration<double>(Clock::now() - node_start).count(),
                         std::move(context.warnings), std::move(context.fill)});
    if (!output.ok()) {
      run.status = output.status().WithContext(NodeLabel(planned.id, planned.spec->type));
      run.failed_node = static_cast<int>(i);
      break;
    }
    if (planned.spec->output && last_use_[i] >= 0) values[i] = std::move(output).value();
    for (const auto& [port, producer] : planned.inputs)
      if (last_use_[producer] == static_cast<int>(i)) values[producer].reset();
    if (on_node_done) on_node_done(planned);
  }
  run.total_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return run;
}

Result<NodeOptions> CheckNodeOptions(const NodeTypeSpec& spec,
                                     const std::vector<std::pair<std::string, OptionValue>>& given,
                                     const std::function<std::string(const std::string&)>& label) {
  const auto name_of = [&](const std::string& name) { return label ? label(name) : "option \"" + name + "\""; };
  std::map<std::string, OptionValue> values;
  std::vector<std::string> names, problems;
  for (const OptionSpec& option : spec.options) names.push_back(option.name);
  std::set<std::string> seen;
  for (const auto& [name, value] : given) {
    const OptionSpec* option = nullptr;
    for (const OptionSpec& o : spec.options)
      if (o.name == name) option = &o;
    if (!option) {
      problems.push_back(name_of(name) + ": unknown option (" + spec.type + " has: " +
                         (names.empty() ? std::string("no options") : NameList(names)) + ")");
    } else if (!seen.insert(name).second) {  // a reader that allows duplicate keys
      problems.push_back(name_of(name) + ": given twice");
    } else if (Status s = CheckOption(*option, value); !s.ok()) {
      problems.push_back(name_of(name) + ": " + s.message());
    } else {
      values[name] = value;
    }
  }
  for (const OptionSpec& option : spec.options) {
    if (seen.count(option.name)) continue;
    if (option.required)
      problems.push_back(name_of(option.name) + ": required (" + option.doc + ")");
    else
      values[option.name] = option.default_value;
  }
  if (!problems.empty()) {
    std::string message;
    for (const std::string& p : problems) message += (message.empty() ? "" : "\n") + p;
    return InvalidArgument(message);
  }
  return NodeOptions(std::move(values));
}

}  // namespace mocapfill::graph
