#include "processing/graph/node_registry.h"

namespace mocapfill::graph {

Status NodeRegistry::Register(NodeTypeSpec spec) {
  if (spec.type.empty() || !spec.create) return Internal("node type '" + spec.type + "' has no name or factory");
  if (specs_.count(spec.type)) return Internal("node type '" + spec.type + "' is registered twice");
  for (const OptionSpec& option : spec.options) {
    if (option.default_value.is_null()) continue;
    if (Status s = CheckOption(option, option.default_value); !s.ok())
      return Internal("node type '" + spec.type + "': default of option '" + option.name + "': " + s.message());
  }
  std::string type = spec.type;
  specs_.emplace(std::move(type), std::move(spec));
  return OkStatus();
}

const NodeTypeSpec* NodeRegistry::Find(std::string_view type) const {
  const auto it = specs_.find(type);
  return it == specs_.end() ? nullptr : &it->second;
}

std::vector<std::string> NodeRegistry::Types() const {
  std::vector<std::string> out;
  for (const auto& [type, spec] : specs_) out.push_back(type);
  return out;
}

}  // namespace mocapfill::graph
