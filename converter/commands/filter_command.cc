// mocapfill filter: multiresolution filtering (Bruderlin-Williams band gains) of a motion
// file, written through the exporters (validator-clean glTF, or BVH). The verb runs the
// pipeline's filter node, and its flags are generated from that node's option schema, so
// the two accept the same options with the same ranges.
#include <cstdio>
#include <filesystem>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/database_arg.h"
#include "converter/exit_codes.h"
#include "converter/export_flags.h"
#include "converter/import_flags.h"
#include "converter/node_flags.h"
#include "formats/file_io.h"
#include "formats/motion_io.h"
#include "processing/filtering/pyramid.h"
#include "processing/graph/nodes/nodes.h"

namespace mocapfill::cli {

namespace {

namespace fs = std::filesystem;

struct FilterArgs {
  std::string input;
  std::string output;
  std::string db;
  ImportOptions import;
  ExportOptions export_options;
  NodeFlags flags;  // the filter node's options
};

// "filtered 'walk': 40 frames, 5 levels: L0 15Hz x1 ...": what each band was scaled by.
void PrintBands(const MotionClip& clip, const graph::NodeOptions& options) {
  if (IsQuiet()) return;
  const std::vector<double> gains = options.NumberList("gains");
  const int levels = options.Int("levels") > 0 ? options.Int("levels") : AutomaticLevels(clip.num_frames, clip.sample_rate_hz);
  std::string bands;
  char buffer[64];
  for (int k = 0; k < levels; ++k) {
    const double g = k < static_cast<int>(gains.size()) ? gains[k] : 1.0;
    std::snprintf(buffer, sizeof(buffer), " L%d %.2gHz x%g", k, BandPeakHz(k, clip.sample_rate_hz), g);
    bands += buffer;
  }
  std::printf("filtered '%s': %d frames, %d levels:%s, residual x%g\n", clip.name.c_str(), clip.num_frames, levels,
              bands.c_str(), options.Number("residual_gain"));
}

int RunFilter(const FilterArgs& args) {
  const graph::NodeTypeSpec spec = graph::FilterNodeSpec();
  Result<graph::NodeOptions> options = NodeOptionsFromFlags(spec, args.flags);
  if (!options.ok()) return Fail(options.status(), Stage::kProcessing);
  Result<std::unique_ptr<graph::Node>> node = spec.create(*options);
  if (!node.ok()) return Fail(node.status(), Stage::kProcessing);
  if (!IsExportExtension(args.output)) return Fail(InvalidArgument(args.output + ": output must end in .gltf, .glb or .bvh"), Stage::kOutput);
  if (IsSameFile(args.input, args.output) ||
      fs::path(args.input).lexically_normal() == fs::path(args.output).lexically_normal())
    return Fail(IoError(args.output + ": refusing to overwrite the input file"), Stage::kOutput);
  Result<Scene> scene = ImportFile(args.input, args.import);
  if (!scene.ok()) return Fail(scene.status(), Stage::kInput);
  for (const std::string& warning : scene->warnings) PrintWarning(args.input + ": " + warning);
  if (scene->clips.empty()) return Fail(InvalidData(args.input + ": no animation to filter"), Stage::kInput);

  graph::NodeInputs inputs;
  inputs.Set("motion", graph::Value(std::make_shared<const Scene>(std::move(scene).value())));
  if (!args.db.empty()) {
    Result<MotionDatabase> db = LoadDatabaseArg(args.db);
    if (!db.ok()) return Fail(db.status(), Stage::kInput);
    inputs.Set("database", graph::Value(std::make_shared<const MotionDatabase>(std::move(db).value())));
  }
  graph::RunContext context;
  Result<graph::Value> filtered = (*node)->Run(inputs, context);
  for (const std::string& warning : context.warnings) PrintWarning(args.input + ": " + warning);
  if (!filtered.ok()) return Fail(filtered.status().WithContext(args.input), Stage::kInput);
  const Scene& out = *std::get<std::shared_ptr<const Scene>>(*filtered);
  for (const MotionClip& clip : out.clips) PrintBands(clip, *options);
  const Status written = ExportFile(out, args.output, args.export_options);
  if (!written.ok()) return Fail(written, Stage::kOutput);
  return kExitOk;
}

}  // namespace

void AddFilterCommand(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<FilterArgs>();
  CLI::App* command = app.add_subcommand(
      "filter", "Multiresolution filtering: scale frequency bands of the motion (Bruderlin-Williams)");
  command->add_option("input", args->input, "Input motion file (.bvh .gltf .glb .fbx)")->required();
  command->add_option("-o,--output", args->output, "Output file (.glb .gltf .bvh)")->required();
  AddNodeFlags(*command, graph::FilterNodeSpec(), args->flags);
  command->add_option("--db", args->db, "Filter about this database's joint means (.mfdb file, motion folder or default)");
  AddImportFlags(*command, args->import);
  AddExportFlags(*command, args->export_options);
  command->footer(
      "Examples:\n"
      "  mocapfill filter walk.bvh -o lively.glb --gains 1,1,1.5,1.5,1,1\n"
      "  mocapfill filter walk.bvh -o arms.glb --gains 1,1,2 --joints UpperArm_L,LowerArm_L\n"
      "\n"
      "The options are those of the pipeline's filter node (mocapfill run --list-nodes): gains per band,\n"
      "L0 the highest (about 15 Hz at 30 Hz), missing gains 1; levels 0 = floor(log2 frames), lowest band >= 0.1 Hz.");
  command->callback([args, &action] { action = [args] { return RunFilter(*args); }; });
}

}  // namespace mocapfill::cli
