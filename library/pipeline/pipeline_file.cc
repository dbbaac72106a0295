#include "library/pipeline/pipeline_file.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "formats/file_io.h"

namespace mocapfill {

namespace {

using graph::NodeConfig;
using graph::OptionValue;
using Json = nlohmann::ordered_json;

OptionValue ToOptionValue(const Json& json) {
  if (json.is_boolean()) return OptionValue::Bool(json.get<bool>());
  if (json.is_number()) return OptionValue::Number(json.get<double>(), json.is_number_integer());
  if (json.is_string()) return OptionValue::String(json.get<std::string>());
  if (json.is_array()) {
    std::vector<OptionValue> items;
    for (const Json& item : json) items.push_back(ToOptionValue(item));
    return OptionValue::Array(std::move(items));
  }
  if (json.is_object()) {
    std::vector<std::string> keys;
    std::vector<OptionValue> values;
    for (const auto& [key, value] : json.items()) {
      keys.push_back(key);
      values.push_back(ToOptionValue(value));
    }
    return OptionValue::Object(std::move(keys), std::move(values));
  }
  return OptionValue();
}

std::string NodeName(const Json& node, size_t index) {
  if (node.is_object() && node.contains("id") && node["id"].is_string())
    return "node \"" + node["id"].get<std::string>() + "\"";
  return "node #" + std::to_string(index + 1);
}

Result<NodeConfig> ParseNode(const Json& json, size_t index) {
  const std::string name = NodeName(json, index);
  if (!json.is_object()) return InvalidArgument(name + ": expected an object {\"id\", \"type\", \"inputs\", \"options\"}");
  NodeConfig node;
  for (const auto& [key, value] : json.items()) {
    if (key == "id" || key == "type") {
      if (!value.is_string()) return InvalidArgument(name + ": \"" + key + "\": expected a string");
      (key == "id" ? node.id : node.type) = value.get<std::string>();
    } else if (key == "inputs") {
      if (!value.is_object()) return InvalidArgument(name + ": \"inputs\": expected an object {port: node id}");
      for (const auto& [port, producer] : value.items()) {
        if (!producer.is_string())
          return InvalidArgument(name + ": input \"" + port + "\": expected the id of a node (a string)");
        node.inputs.emplace_back(port, producer.get<std::string>());
      }
    } else if (key == "options") {
      if (!value.is_object()) return InvalidArgument(name + ": \"options\": expected an object {option: value}");
      for (const auto& [option, option_value] : value.items()) node.options.emplace_back(option, ToOptionValue(option_value));
    } else if (key != "comment") {
      return InvalidArgument(name + ": unknown field \"" + key + "\" (expected id, type, inputs, options, comment)");
    }
  }
  if (node.id.empty()) return InvalidArgument(name + ": \"id\" is missing");
  if (node.type.empty()) return InvalidArgument(name + ": \"type\" is missing");
  return node;
}

// nlohmann's "[json.exception.parse_error.101] parse error at line 2, ..." without the tag.
std::string ParseErrorText(const std::string& what) {
  const size_t tag_end = what.find("] ");
  return tag_end == std::string::npos ? what : what.substr(tag_end + 2);
}

void ResolvePaths(const graph::NodeRegistry& registry, const std::filesystem::path& base, graph::GraphConfig& config) {
  for (NodeConfig& node : config.nodes) {
    const graph::NodeTypeSpec* spec = registry.Find(node.type);
    if (!spec) continue;  // validation reports it
    for (auto& [name, value] : node.options) {
      for (const graph::OptionSpec& option : spec->options) {
        if (option.name != name || option.type != graph::OptionType::kPath) continue;
        if (value.kind != OptionValue::Kind::kString || value.text.empty()) continue;
        if (std::find(option.choices.begin(), option.choices.end(), value.text) != option.choices.end()) continue;
        const std::filesystem::path path(value.text);
        if (path.is_relative()) value.text = (base / path).lexically_normal().string();
      }
    }
  }
}

}  // namespace

Result<PipelineFile> ParsePipelineJson(const std::string& text) {
  Json json;
  try {
    json = Json::parse(text);
  } catch (const Json::exception& e) {  // parse_error, or out_of_range for a number like 1e999
    return InvalidArgument("invalid JSON: " + ParseErrorText(e.what()));
  }
  if (!json.is_object()) return InvalidArgument("expected a JSON object {\"version\": 1, \"nodes\": [...]}");
  PipelineFile file;
  bool has_version = false;
  for (const auto& [key, value] : json.items()) {
    if (key == "version") {
      if (!value.is_number_integer()) return InvalidArgument("\"version\": expected an integer (1)");
      file.config.version = value.get<int>();
      has_version = true;
    } else if (key == "description") {
      if (!value.is_string()) return InvalidArgument("\"description\": expected a string");
      file.description = value.get<std::string>();
    } else if (key == "nodes") {
      if (!value.is_array()) return InvalidArgument("\"nodes\": expected an array of nodes");
      for (size_t i = 0; i < value.size(); ++i) {
        ASSIGN_OR_RETURN(NodeConfig node, ParseNode(value[i], i));
        file.config.nodes.push_back(std::move(node));
      }
    } else {
      return InvalidArgument("unknown field \"" + key + "\" (expected version, description, nodes)");
    }
  }
  if (!has_version) return InvalidArgument("\"version\" is missing (this build reads version 1)");
  if (!json.contains("nodes")) return InvalidArgument("\"nodes\" is missing");
  return file;
}

Result<PipelineFile> ReadPipelineFile(const std::string& path, const graph::NodeRegistry& registry) {
  ASSIGN_OR_RETURN(const std::string text, ReadFileBytes(path));
  Result<PipelineFile> file = ParsePipelineJson(text);
  if (!file.ok()) return file.status().WithContext(path);
  file->path = path;
  ResolvePaths(registry, std::filesystem::path(path).parent_path(), file->config);
  return file;
}

Status ApplyOverrides(const std::vector<std::string>& overrides, graph::GraphConfig& config) {
  for (const std::string& text : overrides) {
    const size_t dot = text.find('.'), eq = text.find('=');
    if (dot == std::string::npos || eq == std::string::npos || dot == 0 || eq < dot + 2)
      return InvalidArgument("--set \"" + text + "\": expected node.option=value, e.g. fill.method=nn");
    const std::string id = text.substr(0, dot), option = text.substr(dot + 1, eq - dot - 1);
    const std::string raw = text.substr(eq + 1);
    const Json json = Json::parse(raw, nullptr, /*allow_exceptions=*/false);
    const OptionValue value = json.is_discarded() ? OptionValue::String(raw) : ToOptionValue(json);
    NodeConfig* node = nullptr;
    for (NodeConfig& n : config.nodes)
      if (n.id == id) node = &n;
    if (!node) return InvalidArgument("--set \"" + text + "\": no node \"" + id + "\" in the pipeline");
    bool replaced = false;
    for (auto& [name, current] : node->options)
      if (name == option) current = value, replaced = true;
    if (!replaced) node->options.emplace_back(option, value);
  }
  return OkStatus();
}

}  // namespace mocapfill
