#include "library/pipeline/pipeline_session.h"

#include <map>
#include <nlohmann/json.hpp>

#include "formats/file_io.h"
#include "library/fill_report_json.h"

namespace mocapfill {

namespace {

using graph::PlannedNode;

bool IsPathOption(const PlannedNode& node, const std::string& name) {
  for (const graph::OptionSpec& option : node.spec->options)
    if (option.name == name) return option.type == graph::OptionType::kPath;
  return false;
}

std::string Label(const PlannedNode& node) { return graph::NodeLabel(node.id, node.spec->type); }

std::string OptionDetails(const graph::OptionSpec& option) {
  std::string text = std::string(graph::OptionTypeName(option.type));
  if (option.required) text += ", required";
  else if (!option.default_value.is_null()) text += ", default " + graph::FormatOptionValue(option.default_value);
  else text += ", optional";
  if (!option.unit.empty()) text += ", " + option.unit;
  if (option.min || option.max) {
    text += option.type == graph::OptionType::kInt || option.type == graph::OptionType::kNumber ? ", " : ", each ";
    if (option.min) text += (option.min_exclusive ? "> " : ">= ") + graph::FormatOptionValue(graph::OptionValue::Number(*option.min, false));
    if (option.min && option.max) text += " and ";
    if (option.max) text += "<= " + graph::FormatOptionValue(graph::OptionValue::Number(*option.max, false));
  }
  if (!option.choices.empty() && option.type == graph::OptionType::kString) {
    text += ", one of";
    for (const std::string& c : option.choices) text += " " + c;
  }
  return text;
}

}  // namespace

Status CheckOutputPaths(const graph::Graph& graph) {
  std::map<std::string, std::string> written;  // path -> node label
  for (const PlannedNode& sink : graph.plan()) {
    if (sink.spec->role != graph::NodeRole::kSink || !sink.options.Has("path")) continue;
    const std::string& out = sink.options.String("path");
    const auto [it, fresh] = written.emplace(out, Label(sink));
    if (!fresh) return InvalidArgument(Label(sink) + ": option \"path\": " + it->second + " writes \"" + out + "\" too");
    for (const PlannedNode& source : graph.plan()) {
      if (source.spec->role == graph::NodeRole::kSink) continue;
      for (const auto& [name, value] : source.options.values())
        if (IsPathOption(source, name) && value.kind == graph::OptionValue::Kind::kString && IsSameFile(value.text, out))
          return IoError(Label(sink) + ": option \"path\": refusing to overwrite \"" + out + "\", an input of " +
                         Label(source));
    }
  }
  return OkStatus();
}

std::string DescribePlan(const PipelineFile& file, const graph::Graph& graph) {
  std::string text = "pipeline " + file.path + ": " + std::to_string(graph.plan().size()) + " nodes, valid\n";
  if (!file.description.empty()) text += "  " + file.description + "\n";
  for (size_t i = 0; i < graph.plan().size(); ++i) {
    const PlannedNode& node = graph.plan()[i];
    text += std::to_string(i + 1) + ". " + node.id + " (" + node.spec->type + ")";
    if (node.spec->output) text += " -> " + std::string(graph::PortTypeName(node.spec->output->type));
    text += "\n";
    for (const auto& [port, producer] : node.inputs)
      text += "     input  " + port + " <- " + graph.plan()[producer].id + "\n";
    for (const auto& [name, value] : node.options.values())
      if (!value.is_null()) text += "     option " + name + " = " + graph::FormatOptionValue(value) + "\n";
  }
  return text;
}

std::string DescribeNodeTypes(const graph::NodeRegistry& registry) {
  std::string text;
  for (const std::string& type : registry.Types()) {
    const graph::NodeTypeSpec& spec = *registry.Find(type);
    text += type + ": " + spec.summary + "\n";
    for (const graph::PortSpec& port : spec.inputs)
      text += "  input  " + port.name + " (" + graph::PortTypeName(port.type) + (port.optional ? ", optional" : "") +
              "): " + port.doc + "\n";
    if (spec.output) text += "  output " + std::string(graph::PortTypeName(spec.output->type)) + ": " + spec.output->doc + "\n";
    for (const graph::OptionSpec& option : spec.options) {
      // The command line's own spelling, where the verb's flag is not the name's.
      std::string flag;
      if (!option.flag.empty()) flag = "--" + option.flag;
      if (option.words.size() == 2) flag = (flag.empty() ? "" : flag + " ") + option.words[0] + "|" + option.words[1];
      text += "  option " + option.name + " (" + OptionDetails(option) + (flag.empty() ? "" : "; flag " + flag) +
              "): " + option.doc + "\n";
    }
    text += "\n";
  }
  return text;
}

std::string RunReportJson(const PipelineFile& file, const graph::GraphRun& run) {
  nlohmann::ordered_json json;
  json["pipeline"] = file.path;
  json["ok"] = run.status.ok();
  if (!run.status.ok()) json["error"] = run.status.message();
  json["total_seconds"] = run.total_seconds;
  nlohmann::ordered_json nodes = nlohmann::ordered_json::array();
  for (const graph::NodeRun& node : run.nodes) {
    nodes.push_back({{"id", node.id}, {"type", node.type}, {"seconds", node.seconds}, {"warnings", node.warnings}});
    // A fill node's report, as `fill --report` writes it; its key errors are measured on the
    // filled clip in memory, before an output node writes it.
    if (node.fill) {
      nodes.back()["report"] = nlohmann::ordered_json::parse(FillReportJson(*node.fill, "input \"database\"", 0.0));
      nodes.back()["report_key_errors_measured"] = "on the filled clip in memory, before it is written";
    }
  }
  json["nodes"] = nodes;
  return json.dump(2) + "\n";
}

FailureStage StageOf(graph::NodeRole role) {
  switch (role) {
    case graph::NodeRole::kSource: return FailureStage::kInput;
    case graph::NodeRole::kSink: return FailureStage::kOutput;
    case graph::NodeRole::kProcess: return FailureStage::kProcessing;
  }
  return FailureStage::kProcessing;
}

}  // namespace mocapfill
