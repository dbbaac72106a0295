// Command-line flags generated from a node type's option schema (processing/graph), so that
// a verb and its pipeline node take the same options, with the same defaults, ranges and
// messages: `residual_gain` is `--residual-gain` (or the spec's own `flag` spelling), lists
// are comma-separated, maps are `key=value,...`, booleans are flags (or `--name=false`), or
// take one of the spec's two words (`--feet plant|free`).
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "processing/graph/node.h"

namespace mocapfill::cli {

// The generated flags and what the user gave for them, as text, by option name.
struct NodeFlags {
  std::map<std::string, std::string> text;                // single values
  std::map<std::string, std::vector<std::string>> lists;  // list and map options, item by item
  std::map<std::string, CLI::Option*> options;
  // Values the verb sets its own way (`pca edit --drop-residual` is keep_residual = false),
  // checked with the flags.
  std::vector<std::pair<std::string, graph::OptionValue>> fixed;
};

// Adds a flag per option of `spec`, except those named in `skip` (a verb that takes them
// its own way, such as a file path as a positional argument).
void AddNodeFlags(CLI::App& command, const graph::NodeTypeSpec& spec, NodeFlags& flags,
                  const std::set<std::string>& skip = {});

// The given flags parsed by their option's type and checked against the schema, defaults
// added. kInvalidArgument naming the flag ("--gains: expected a number <= 10, got 20").
Result<graph::NodeOptions> NodeOptionsFromFlags(const graph::NodeTypeSpec& spec, const NodeFlags& flags);

// The `--flag` of an option name ('_' written '-').
std::string FlagName(const std::string& option);

// The `--flag` of each option of `spec` by option name (its `flag` spelling where it has one):
// the label of messages about flags.
std::function<std::string(const std::string&)> FlagLabel(const graph::NodeTypeSpec& spec);

}  // namespace mocapfill::cli
