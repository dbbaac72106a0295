// Pipeline files (`mocapfill run pipeline.json`, docs/pipeline.md): JSON read with
// nlohmann-json into the graph core's plain GraphConfig, relative paths resolved against the
// file's folder, and `--set node.option=value` overrides applied.
//
//   {"version": 1, "description": "...",
//    "nodes": [{"id": "sketch", "type": "import", "options": {"path": "walk.glb"}},
//              {"id": "out", "type": "export", "inputs": {"motion": "sketch"},
//               "options": {"path": "out.glb"}}]}
#pragma once

#include <string>
#include <vector>

#include "processing/core/status.h"
#include "processing/graph/graph.h"
#include "processing/graph/node_registry.h"

namespace mocapfill {

struct PipelineFile {
  std::string path;         // as given
  std::string description;  // optional "description" of the file
  graph::GraphConfig config;
};

// Parses pipeline JSON. Errors are kInvalidArgument naming the JSON line/column or the node
// and field ("node \"fill\": \"inputs\": expected an object {port: node id}").
Result<PipelineFile> ParsePipelineJson(const std::string& text);

// Reads and parses a pipeline file (unreadable: kIoError), then resolves the relative values
// of every path option (OptionType::kPath of the node types in `registry`) against the
// file's folder; words such as "default" listed in the option's choices are left alone.
Result<PipelineFile> ReadPipelineFile(const std::string& path, const graph::NodeRegistry& registry);

// Applies "node.option=value" overrides. The value is JSON when it parses as JSON (64, true,
// [1, 2], "x"), else a string (nn, out.glb); paths given here are taken as written (relative
// to the current directory). Unknown node id or a malformed override: kInvalidArgument.
Status ApplyOverrides(const std::vector<std::string>& overrides, graph::GraphConfig& config);

}  // namespace mocapfill
