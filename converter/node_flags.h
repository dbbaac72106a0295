// Command-line flags generated from a node type's option schema (processing/graph), so that
// a verb and its pipeline node take the same options, with the same defaults, ranges and
// messages: `residual_gain` is `--residual-gain`, lists are comma-separated, maps are
// `key=value,...`, booleans are flags (or `--name=false`).
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <memory>
#include <set>
#include <string>

#include "processing/graph/node.h"

namespace mocapfill::cli {

// The generated flags and what the user gave for them, as text, by option name.
struct NodeFlags {
  std::map<std::string, std::string> text;
  std::map<std::string, CLI::Option*> options;
};

// Adds a flag per option of `spec`, except those named in `skip` (a verb that takes them
// its own way, such as a file path as a positional argument).
void AddNodeFlags(CLI::App& command, const graph::NodeTypeSpec& spec, NodeFlags& flags,
                  const std::set<std::string>& skip = {});

// The given flags parsed by their option's type and checked against the schema, defaults
// added. kInvalidArgument naming the flag ("--gains: expected a number <= 10, got 20").
Result<graph::NodeOptions> NodeOptionsFromFlags(const graph::NodeTypeSpec& spec, const NodeFlags& flags);

// The `--flag` of an option name.
std::string FlagName(const std::string& option);

}  // namespace mocapfill::cli
