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
  // A leading '+' (a dial's "1=+1.5") is a sign from_chars does not take.
  const char* begin = text.size() > 1 && text[0] == '+' && text[1] != '-' ? text.data() + 1 : text.data();
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end || text.empty()) return OptionValue::String(text);
  return OptionValue::Number(value, text.find_first_of(".eE") == std::string::npos);
}

OptionValue FromText(const OptionSpec& spec, const std::string& text) {
  switch (spec.type) {
    case OptionType::kBool:
      if (spec.words.size() == 2 && text == spec.words[0]) return OptionValue::Bool(true);
      if (spec.words.size() == 2 && text == spec.words[1]) return OptionValue::Bool(false);
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

bool IsList(OptionType type) { return type == OptionType::kNumberList || type == OptionType::kStringList; }
bool IsMap(OptionType type) { return type == OptionType::kNumberMap || type == OptionType::kStringMap; }

std::string Help(const OptionSpec& spec) {
  std::string help = spec.doc;
  if (IsList(spec.type)) help += "; comma-separated";
  if (IsMap(spec.type)) help += "; key=value,...";
  if (!spec.choices.empty() && spec.type == OptionType::kString) {
    help += " (";
    for (size_t i = 0; i < spec.choices.size(); ++i) help += (i ? ", " : "") + spec.choices[i];
    help += ")";
  }
  if (spec.type == OptionType::kBool && spec.words.size() == 2) {
    help += " (" + spec.words[0] + " or " + spec.words[1] + ") [default: " +
            spec.words[spec.default_value.boolean ? 0 : 1] + "]";
  } else if (!spec.default_value.is_null() && !IsList(spec.type) && !IsMap(spec.type)) {
    help += " [default: " + graph::FormatOptionValue(spec.default_value) + "]";
  }
  return help;
}

std::string FlagOf(const OptionSpec& spec) { return FlagName(spec.flag.empty() ? spec.name : spec.flag); }

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
    const std::string flag_name = FlagOf(option);
    CLI::Option* flag = nullptr;
    if (IsList(option.type) || IsMap(option.type)) {
      // Comma-separated, and repeatable: `--dial 1=+1 --dial 2=-1` is `--dial 1=+1,2=-1`.
      // One value per occurrence: `--keep Hips sketch.glb` leaves the positional alone.
      flag = command.add_option(flag_name, flags.lists[option.name], Help(option))
                 ->delimiter(',')
                 ->allow_extra_args(false)
                 ->type_name(graph::OptionTypeName(option.type));
    } else if (option.type == OptionType::kBool && option.words.size() != 2) {
      // A switch: `--periodic` alone is true, `--periodic=false` says so explicitly.
      flag = command.add_flag(flag_name + "{true}", flags.text[option.name], Help(option));
    } else {
      const std::string type_name = option.type == OptionType::kBool ? option.words[0] + "|" + option.words[1]
                                                                     : graph::OptionTypeName(option.type);
      flag = command.add_option(flag_name, flags.text[option.name], Help(option))->type_name(type_name);
    }
    flags.options[option.name] = flag;
  }
}

Result<graph::NodeOptions> NodeOptionsFromFlags(const graph::NodeTypeSpec& spec, const NodeFlags& flags) {
  std::vector<std::pair<std::string, OptionValue>> given = flags.fixed;
  for (const OptionSpec& option : spec.options) {
    const auto it = flags.options.find(option.name);
    if (it == flags.options.end() || it->second->count() == 0) continue;
    std::string text;
    if (const auto list = flags.lists.find(option.name); list != flags.lists.end()) {
      for (const std::string& item : list->second) text += (text.empty() ? "" : ",") + item;
    } else {
      text = flags.text.at(option.name);
    }
    if (IsMap(option.type))
      for (const std::string& item : SplitCommas(text))
        if (item.find('=') == std::string::npos)
          return InvalidArgument(FlagOf(option) + ": \"" + item + "\": expected <key>=<value>, e.g. " +
                                 (option.type == OptionType::kNumberMap ? "1=+2.0" : "Hip=hips"));
    given.emplace_back(option.name, FromText(option, text));
  }
  return graph::CheckNodeOptions(spec, given, FlagLabel(spec));
}

std::function<std::string(const std::string&)> FlagLabel(const graph::NodeTypeSpec& spec) {
  return [options = spec.options](const std::string& name) {
    for (const OptionSpec& option : options)
      if (option.name == name) return FlagOf(option);
    return FlagName(name);
  };
}

}  // namespace mocapfill::cli
