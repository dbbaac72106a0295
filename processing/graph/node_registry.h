// The node types a graph may use, by type name. The converter fills one registry with the
// algorithm nodes (processing_nodes.h) and its own file nodes (import, export, ...).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "processing/graph/node.h"

namespace mocapfill::graph {

class NodeRegistry {
 public:
  // kInternal when the type is already registered or the spec is malformed (no factory,
  // a default value that fails its own option check): both are bugs of ours.
  Status Register(NodeTypeSpec spec);
  const NodeTypeSpec* Find(std::string_view type) const;
  std::vector<std::string> Types() const;  // sorted

 private:
  std::map<std::string, NodeTypeSpec, std::less<>> specs_;
};

}  // namespace mocapfill::graph
