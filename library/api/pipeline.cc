#include "mocapfill/pipeline.h"

#include "library/api/access.h"
#include "library/pipeline/file_nodes.h"
#include "library/pipeline/pipeline_file.h"
#include "library/pipeline/pipeline_session.h"

namespace mocapfill::api {

namespace {

struct LoadedPipeline {
  PipelineFile file;
  graph::Graph graph;
};

// The file read, overridden and validated as a whole (the checks of `mocapfill run`).
LoadedPipeline Load(const graph::NodeRegistry& registry, const std::string& path, const std::vector<std::string>& sets) {
  PipelineFile file = ValueOrThrow(ReadPipelineFile(path, registry), FailureStage::kInput);
  ThrowIfError(ApplyOverrides(sets, file.config).WithContext(path), FailureStage::kInput);
  graph::Graph graph = ValueOrThrow(graph::Graph::Build(file.config, registry), FailureStage::kInput);
  ThrowIfError(CheckOutputPaths(graph).WithContext(path), FailureStage::kOutput);
  return {std::move(file), std::move(graph)};
}

}  // namespace

PipelineResult RunPipeline(const std::string& path, const std::vector<std::string>& sets) {
  const graph::NodeRegistry registry = ValueOrThrow(MakePipelineRegistry(), FailureStage::kProcessing);
  LoadedPipeline pipeline = Load(registry, path, sets);
  const graph::GraphRun run = pipeline.graph.Run({});
  PipelineResult result;
  result.report_json = RunReportJson(pipeline.file, run);
  result.seconds = run.total_seconds;
  for (const graph::NodeRun& node : run.nodes)
    for (const std::string& w : node.warnings) result.warnings.push_back(graph::NodeLabel(node.id, node.type) + ": " + w);
  if (!run.status.ok())
    ThrowIfError(run.status.WithContext(path), StageOf(pipeline.graph.plan()[run.failed_node].spec->role));
  return result;
}

std::string DescribePipeline(const std::string& path, const std::vector<std::string>& sets) {
  const graph::NodeRegistry registry = ValueOrThrow(MakePipelineRegistry(), FailureStage::kProcessing);
  const LoadedPipeline pipeline = Load(registry, path, sets);
  return DescribePlan(pipeline.file, pipeline.graph);
}

std::string PipelineNodeTypes() {
  return DescribeNodeTypes(ValueOrThrow(MakePipelineRegistry(), FailureStage::kProcessing));
}

}  // namespace mocapfill::api
