// What running a pipeline file takes around the graph core (`mocapfill run`, api::RunPipeline):
// checks that outputs never overwrite inputs, describes the plan (--dry-run) and the node types
// (--list-nodes), and the per-node timing report (--report run.json).
#pragma once

#include <string>

#include "library/failure_class.h"
#include "library/pipeline/pipeline_file.h"
#include "processing/graph/graph.h"

namespace mocapfill {

// Before anything runs: an export path naming an input file (kIoError: exit 4), or two
// exports writing the same file (kInvalidArgument), names the nodes.
Status CheckOutputPaths(const graph::Graph& graph);

// The validated plan, one node per line in run order with its inputs and every option
// (defaults included), for --dry-run.
std::string DescribePlan(const PipelineFile& file, const graph::Graph& graph);

// Every node type: ports and options with types, defaults, units and ranges (--list-nodes;
// the README and docs/pipeline.md tables follow it).
std::string DescribeNodeTypes(const graph::NodeRegistry& registry);

// Where a node's failure belongs: sources read input, sinks write output.
FailureStage StageOf(graph::NodeRole role);

// {"pipeline", "ok", "error", "total_seconds", "nodes": [{"id", "type", "seconds", "warnings"}]}.
std::string RunReportJson(const PipelineFile& file, const graph::GraphRun& run);

}  // namespace mocapfill
