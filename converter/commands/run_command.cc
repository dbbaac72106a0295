// mocapfill run: reads a pipeline file (a processing graph in JSON, docs/pipeline.md),
// validates the whole graph before any node runs, then runs it node by node.
#include <cstdio>
#include <iostream>
#include <sstream>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/database_arg.h"
#include "converter/exit_codes.h"
#include "library/pipeline/file_nodes.h"
#include "library/pipeline/pipeline_file.h"
#include "library/pipeline/pipeline_session.h"
#include "formats/file_io.h"

namespace mocapfill::cli {

namespace {

struct RunArgs {
  std::string pipeline, report;
  std::vector<std::string> sets;
  bool dry_run = false, list_nodes = false, json = false;
};

// Multi-line validation messages get the pipeline file on every line.
int Fail(const std::string& file, const Status& status, Stage stage) {
  std::istringstream lines(status.message());
  for (std::string line; std::getline(lines, line);) PrintError(file.empty() ? line : file + ": " + line);
  return ExitCodeFor(status, stage);
}

int RunPipeline(const RunArgs& args) {
  // The database node loads as the verbs do, with a progress bar on a terminal.
  Result<graph::NodeRegistry> registry = MakePipelineRegistry(
      [](const std::vector<std::string>& paths, const DatabaseBuildOptions& options) { return LoadDatabase(paths, options); });
  if (!registry.ok()) return Fail("", registry.status(), Stage::kProcessing);
  if (args.list_nodes) {
    std::cout << DescribeNodeTypes(*registry);
    return kExitOk;
  }
  if (args.pipeline.empty()) return Fail("", InvalidArgument("give a pipeline file (or --list-nodes)"), Stage::kInput);
  Result<PipelineFile> file = ReadPipelineFile(args.pipeline, *registry);
  if (!file.ok()) return Fail("", file.status(), Stage::kInput);
  if (Status set = ApplyOverrides(args.sets, file->config); !set.ok()) return Fail(args.pipeline, set, Stage::kInput);
  Result<graph::Graph> graph = graph::Graph::Build(file->config, *registry);
  if (!graph.ok()) return Fail(args.pipeline, graph.status(), Stage::kInput);
  if (Status outputs = CheckOutputPaths(*graph); !outputs.ok()) return Fail(args.pipeline, outputs, Stage::kOutput);
  if (args.dry_run) {
    std::cout << DescribePlan(*file, *graph);
    return kExitOk;
  }
  graph::GraphRun run;
  {
    Progress progress("pipeline", graph->plan().size());
    run = graph->Run([&](const graph::PlannedNode&) { progress.Advance(); });
  }
  for (const graph::NodeRun& node : run.nodes)
    for (const std::string& w : node.warnings) PrintWarning(graph::NodeLabel(node.id, node.type) + ": " + w);
  const std::string report = RunReportJson(*file, run);
  if (!args.report.empty())
    if (Status written = WriteFileAtomic(args.report, report); !written.ok()) return Fail("", written, Stage::kOutput);
  if (args.json) std::fputs(report.c_str(), stdout);
  if (!run.status.ok())
    return Fail(args.pipeline, run.status, StageOf(graph->plan()[run.failed_node].spec->role));
  if (!IsQuiet()) {
    std::fprintf(stderr, "run: %zu nodes in %.2f s:", run.nodes.size(), run.total_seconds);
    for (const graph::NodeRun& node : run.nodes) std::fprintf(stderr, " %s %.2f s", node.id.c_str(), node.seconds);
    std::fprintf(stderr, "\n");
  }
  return kExitOk;
}

}  // namespace

void AddRunCommand(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<RunArgs>();
  CLI::App* command = app.add_subcommand("run", "Run a processing pipeline described in JSON (docs/pipeline.md)");
  command->add_option("pipeline", args->pipeline, "Pipeline file (.json); relative paths in it are relative to its folder");
  command->add_option("--set", args->sets, "Override an option: node.option=value (JSON or plain text); repeatable");
  command->add_flag("--dry-run", args->dry_run, "Validate the pipeline and print the plan; run nothing");
  command->add_option("--report", args->report,
                      "Write per-node timings and warnings as JSON, with each fill node's report (as fill --report)");
  command->add_flag("--json", args->json, "Print that JSON report on standard output");
  command->add_flag("--list-nodes", args->list_nodes, "Print every node type with its ports and options");
  command->footer(
      "Examples:\n"
      "  mocapfill run fixtures/pipelines/fill_default.json\n"
      "  mocapfill run fill.json --set fill.method=fragment --set out.path=walk_fragment.glb\n"
      "  mocapfill run fill.json --dry-run\n"
      "  mocapfill run fill.json --report run.json\n"
      "  mocapfill run --list-nodes");
  command->callback([args, &action] { action = [args] { return RunPipeline(*args); }; });
}

}  // namespace mocapfill::cli
