// Processing pipelines: a graph of nodes (import, database, fill, filter, texture, PCA,
// export) described in a JSON file (docs/pipeline.md), run as `mocapfill run` runs it.
#pragma once

#include <string>
#include <vector>

#include "mocapfill/export.h"

namespace mocapfill::api {

struct PipelineResult {
  // The run report, as `mocapfill run --report` writes it: JSON with per-node seconds and
  // warnings, and each fill node's report (key errors, coverage, fragments).
  std::string report_json;
  std::vector<std::string> warnings;  // "node 'fill' (fill): ..." per warning
  double seconds = 0.0;
};

// Validates the whole pipeline file, with `sets` applied ("node.option=value", as `run --set`),
// then runs it node by node; its export nodes write their files. Throws Error: a bad file or
// option (kUsage / kInput, naming the node and option), a node that fails (the class of its
// failure; files of later exports are not written).
MOCAPFILL_API PipelineResult RunPipeline(const std::string& path, const std::vector<std::string>& sets = {});

// The validated plan, one node per line in run order with every option (as `run --dry-run`);
// nothing runs. Throws Error as RunPipeline.
MOCAPFILL_API std::string DescribePipeline(const std::string& path, const std::vector<std::string>& sets = {});

// Every node type with its ports and options (as `run --list-nodes`).
MOCAPFILL_API std::string PipelineNodeTypes();

}  // namespace mocapfill::api
