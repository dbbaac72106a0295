#include "converter/node_flags.h"

#include <charconv>
#include <sstream>
#include <vector>

#include "processing/graph/option_value.h"

namespace mocapfill::cli {

namespace {

using graph::OptionSpec;
using graph::OptionType;
using graph::OptionValue;

std::vector<std::string> SplitCommas(const std::string& text) {
  std::vector<std::string> parts;
  if (text.empty()) return parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');) parts.push_back(part);
  return parts;
}

// A number written as text, integral when it has no fraction or exponent; a string value
// otherwise, which the schema check then refuses with its own message ("expected a number").
OptionValue NumberOrText(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end || text.empty()) return OptionValue::String(text);
  return OptionValue::Number(value, text.find_first_of(".eE") == std::string::npos);
}

OptionValue FromText(const OptionSpec& spec, const std::string& text) {
  switch (spec.type) {
    case OptionType::kBool:
      if (text == "true" || text == "on" || text == "1") return OptionValue::Bool(true);
      if (text == "false" || text == "off" || text == "0") return OptionValue::Bool(false);
      return OptionValue::String(text);
    case OptionType::kInt:
    case OptionType::kNumber: return NumberOrText(text);
    case OptionType::kString:
    case OptionType::kPath: return OptionValue::String(text);
    case OptionType::kNumberList:
    case OptionType::kStringList: {
      std::vector<OptionValue> items;
      for (const std::string& part : SplitCommas(text))
        items.push_back(spec.type == OptionType::kNumberList ? NumberOrText(part) : OptionValue::String(part));
      return OptionValue::Array(std::move(items));
    }
    case OptionType::kNumberMap:
    case OptionType::kStringMap: {
      std::vector<std::string> keys;
      std::vector<OptionValue> values;
      for (const std::string& part : SplitCommas(text)) {
        const size_t eq = part.find('=');
        const std::string value = eq == std::string::npos ? "" : part.substr(eq + 1);
        keys.push_back(part.substr(0, eq));
        values.push_back(spec.type == OptionType::kNumberMap ? NumberOrText(value) : OptionValue::String(value));
      }
      return OptionValue::Object(std::move(keys), std::move(values));
    }
  }
  return OptionValue::String(text);
}

std::string Help(const OptionSpec& spec) {
  std::string help = spec.doc;
  if (spec.type == OptionType::kNumberList || spec.type == OptionType::kStringList) help += "; comma-separated";
  if (spec.type == OptionType::kNumberMap || spec.type == OptionType::kStringMap) help += "; key=value,...";
  if (!spec.choices.empty() && spec.type == OptionType::kString) {
    help += " (";
    for (size_t i = 0; i < spec.choices.size(); ++i) help += (i ? ", " : "") + spec.choices[i];
    help += ")";
  }
  if (!spec.default_value.is_null() && spec.type != OptionType::kNumberList && spec.type != OptionType::kStringList)
    help += " [default: " + graph::FormatOptionValue(spec.default_value) + "]";
  return help;
}

}  // namespace

std::string FlagName(const std::string& option) {
  std::string flag = "--" + option;
  for (char& c : flag)
    if (c == '_') c = '-';
  return flag;
}

void AddNodeFlags(CLI::App& command, const graph::NodeTypeSpec& spec, NodeFlags& flags,
                  const std::set<std::string>& skip) {
  for (const OptionSpec& option : spec.options) {
    if (skip.count(option.name)) continue;
    std::string& text = flags.text[option.name];  // map nodes stay put
    // A boolean is a flag: `--periodic` alone is true, `--periodic=false` says so explicitly.
    CLI::Option* flag = option.type == OptionType::kBool
                            ? command.add_flag(FlagName(option.name) + "{true}", text, Help(option))
                            : command.add_option(FlagName(option.name), text, Help(option))
                                  ->type_name(graph::OptionTypeName(option.type));
    flags.options[option.name] = flag;
  }
}

Result<graph::NodeOptions> NodeOptionsFromFlags(const graph::NodeTypeSpec& spec, const NodeFlags& flags) {
  std::vector<std::pair<std::string, OptionValue>> given;
  for (const OptionSpec& option : spec.options)
    if (const auto it = flags.options.find(option.name); it != flags.options.end() && it->second->count() > 0)
      given.emplace_back(option.name, FromText(option, flags.text.at(option.name)));
  return graph::CheckNodeOptions(spec, given, FlagName);
}

}  // namespace mocapfill::cli
