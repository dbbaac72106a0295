#include "converter/node_flags.h"

#include <sstream>
#include <vector>

#include "processing/graph/option_value.h"

namespace mocapfill::cli {

namespace {

using graph::OptionSpec;
using graph::OptionType;
using graph::OptionValue;

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
    ASSIGN_OR_RETURN(OptionValue value, graph::OptionValueFromText(option, text, FlagOf(option)));
    given.emplace_back(option.name, std::move(value));
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
