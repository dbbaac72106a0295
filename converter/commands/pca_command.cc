// mocapfill pca: principal component models of a motion database.
//   pca build  --db <mfdb|files|folders> -o model.pca [--variance] [--max-components] [--labels]
//   pca info   model.pca [--json]
//   pca edit   in.glb -o out.glb --model model.pca --component 1=+2.0 ...
#include <chrono>
#include <cstdio>
#include <iostream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/database_arg.h"
#include "converter/exit_codes.h"
#include "converter/export_flags.h"
#include "converter/import_flags.h"
#include "converter/node_flags.h"
#include "formats/file_io.h"
#include "formats/motion_io.h"
#include "formats/pca/pca_file.h"
#include "processing/graph/nodes/nodes.h"
#include "processing/pca/pca_model_builder.h"
#include "processing/pca/pca_projection.h"

namespace mocapfill::cli {

namespace {

struct PcaArgs {
  // build
  std::vector<std::string> db;
  std::string output;
  NodeFlags build;  // the pca_build node's options
  // info
  std::string model_path;
  bool json = false;
  // edit
  std::string input;
  NodeFlags edit;  // the pca_edit node's options, but keep_residual (--drop-residual)
  bool drop_residual = false;
  ImportOptions import;
  ExportOptions export_options;
};

int RunBuild(PcaArgs& args) {
  const graph::NodeTypeSpec spec = graph::PcaBuildNodeSpec();
  Result<graph::NodeOptions> options = NodeOptionsFromFlags(spec, args.build);
  if (!options.ok()) return Fail(options.status(), Stage::kProcessing);
  Result<std::unique_ptr<graph::Node>> node = spec.create(*options);
  if (!node.ok()) return Fail(node.status(), Stage::kProcessing);
  if (LowerExtension(args.output) != ".pca")
    return Fail(InvalidArgument(args.output + ": the model file must end in .pca"), Stage::kOutput);
  const auto start = std::chrono::steady_clock::now();
  Result<MotionDatabase> db = LoadDatabase(args.db);
  if (!db.ok()) return Fail(db.status(), Stage::kInput);
  graph::NodeInputs inputs;
  inputs.Set("database", graph::Value(std::make_shared<const MotionDatabase>(std::move(db).value())));
  graph::RunContext context;
  Result<graph::Value> built = (*node)->Run(inputs, context);
  if (!built.ok()) return Fail(built.status(), Stage::kProcessing);
  const std::shared_ptr<const PcaModel> model = std::get<std::shared_ptr<const PcaModel>>(*built);
  if (Status written = WritePcaModel(*model, args.output); !written.ok()) return Fail(written, Stage::kOutput);
  if (!IsQuiet())
    std::fprintf(stderr, "pca build: %d components (%.1f%% of the variance) from %d vectors of %zu clips, %.2f s\n",
                 model->num_components(), 100.0 * ExplainedVarianceRatio(*model, model->num_components()),
                 model->num_samples, model->clips.size(),
                 std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return kExitOk;
}

nlohmann::ordered_json Describe(const PcaModel& m, const std::string& path) {
  nlohmann::ordered_json out;
  out["file"] = path;
  out["kind"] = m.window_frames == 1 ? "pose" : "window";
  out["window_frames"] = m.window_frames;
  out["joints"] = m.num_joints();
  out["root_joint"] = m.root_joint >= 0 ? nlohmann::ordered_json(m.joint_names[m.root_joint]) : nullptr;
  out["root_features"] = m.num_root_features;
  out["rate_hz"] = m.sample_rate_hz;
  out["dimension"] = m.dim();
  out["components"] = m.num_components();
  out["explained_variance"] = ExplainedVarianceRatio(m, m.num_components());
  // Numbers stored per frame (or window) for a motion: coefficients instead of channels.
  out["compression_ratio"] = static_cast<double>(m.dim()) / m.num_components();
  nlohmann::ordered_json cumulative = nlohmann::ordered_json::array();
  for (int k = 1; k <= m.num_components(); ++k) cumulative.push_back(ExplainedVarianceRatio(m, k));
  out["cumulative_explained_variance"] = cumulative;
  std::vector<double> sigmas(m.num_components());
  for (int k = 0; k < m.num_components(); ++k) sigmas[k] = std::sqrt(m.variances[k]);
  out["component_sigma"] = sigmas;  // weighted units (about cm)
  out["samples"] = m.num_samples;
  out["clips"] = m.clips.size();
  out["labels"] = m.labels;
  return out;
}

int RunInfo(const PcaArgs& args) {
  Result<PcaModel> model = ReadPcaModel(args.model_path);
  if (!model.ok()) return Fail(model.status(), Stage::kInput);
  const nlohmann::ordered_json info = Describe(*model, args.model_path);
  if (args.json) {
    std::cout << info.dump(2) << "\n";
    return kExitOk;
  }
  const PcaModel& m = *model;
  std::printf("file:        %s\n", args.model_path.c_str());
  std::printf("model:       %s PCA%s, %d joints + %d root features, %g Hz\n", m.window_frames == 1 ? "pose" : "window",
              m.window_frames == 1 ? "" : (" over " + std::to_string(m.window_frames) + " frames").c_str(),
              m.num_joints(), m.num_root_features, m.sample_rate_hz);
  std::printf("components:  %d of %d (%.2f%% of the variance), compression ratio %.1f:1\n", m.num_components(), m.dim(),
              100.0 * ExplainedVarianceRatio(m, m.num_components()), static_cast<double>(m.dim()) / m.num_components());
  std::printf("built from:  %d vectors of %zu clips%s\n", m.num_samples, m.clips.size(),
              m.labels.empty() ? "" : (", labels " + info["labels"].dump()).c_str());
  std::printf("  k   sigma  cumulative\n");
  for (int k = 0; k < m.num_components(); ++k)
    std::printf("%3d %7.3f  %6.2f%%\n", k + 1, std::sqrt(m.variances[k]), 100.0 * ExplainedVarianceRatio(m, k + 1));
  return kExitOk;
}

int RunEdit(PcaArgs& args) {
  const graph::NodeTypeSpec spec = graph::PcaEditNodeSpec();
  args.edit.fixed = {{"keep_residual", graph::OptionValue::Bool(!args.drop_residual)}};
  Result<graph::NodeOptions> options = NodeOptionsFromFlags(spec, args.edit);
  if (!options.ok()) return Fail(options.status(), Stage::kProcessing);
  Result<std::unique_ptr<graph::Node>> node = spec.create(*options);
  if (!node.ok()) return Fail(node.status(), Stage::kProcessing);
  if (!IsExportExtension(args.output))
    return Fail(InvalidArgument(args.output + ": output must end in .gltf, .glb or .bvh"), Stage::kOutput);
  if (IsSameFile(args.input, args.output)) return Fail(IoError(args.output + ": refusing to overwrite the input"), Stage::kOutput);
  Result<PcaModel> model = ReadPcaModel(args.model_path);
  if (!model.ok()) return Fail(model.status(), Stage::kInput);
  Result<Scene> scene = ImportFile(args.input, args.import);
  if (!scene.ok()) return Fail(scene.status(), Stage::kInput);
  graph::NodeInputs inputs;
  inputs.Set("motion", graph::Value(std::make_shared<const Scene>(std::move(scene).value())));
  inputs.Set("model", graph::Value(std::make_shared<const PcaModel>(std::move(model).value())));
  graph::RunContext context;
  Result<graph::Value> edited = (*node)->Run(inputs, context);
  if (!edited.ok()) {
    // A component beyond the model is the user's choice; a motion without animation, the input's.
    const Stage stage = edited.status().code() == ErrorCode::kInvalidData ? Stage::kInput : Stage::kProcessing;
    return Fail(edited.status().WithContext(args.input), stage);
  }
  const Scene& out = *std::get<std::shared_ptr<const Scene>>(*edited);
  if (Status written = ExportFile(out, args.output, args.export_options); !written.ok()) return Fail(written, Stage::kOutput);
  return kExitOk;
}

}  // namespace

void AddPcaCommand(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<PcaArgs>();
  CLI::App* pca = app.add_subcommand("pca", "Build, inspect and apply PCA models of a motion database");
  pca->require_subcommand(1);
  pca->footer(
      "Examples:\n"
      "  mocapfill pca build --db bn1.mfdb -o walk.pca --labels walk\n"
      "  mocapfill pca info walk.pca --json\n"
      "  mocapfill pca edit walk.glb -o out.glb --model walk.pca --component 1=+2.0");

  CLI::App* build = pca->add_subcommand("build", "Build a PCA model of (some behaviours of) a database");
  build->add_option("--db", args->db, "Database: an .mfdb file or motion files/folders (default: embedded)");
  build->add_option("-o,--output", args->output, "Model file to write (.pca)")->required();
  AddNodeFlags(*build, graph::PcaBuildNodeSpec(), args->build);
  build->footer(
      "Examples:\n"
      "  mocapfill pca build --db bn1.mfdb -o walk.pca --labels walk\n"
      "  mocapfill pca build --db data/bandai -o all.pca --variance 0.99 --max-components 30");
  build->callback([args, &action] { action = [args] { return RunBuild(*args); }; });

  CLI::App* info = pca->add_subcommand("info", "Components, explained variance and compression ratio of a model");
  info->add_option("model", args->model_path, "Model file (.pca)")->required();
  info->add_flag("--json", args->json, "Print JSON instead of text");
  info->footer(
      "Examples:\n"
      "  mocapfill pca info walk.pca\n"
      "  mocapfill pca info walk.pca --json | jq .explained_variance");
  info->callback([args, &action] { action = [args] { return RunInfo(*args); }; });

  CLI::App* edit = pca->add_subcommand("edit", "Move a motion along principal components (in standard deviations)");
  edit->add_option("input", args->input, "Motion to edit (.bvh .gltf .glb .fbx)")->required();
  edit->add_option("-o,--output", args->output, "Output file (.glb .gltf .bvh)")->required();
  edit->add_option("--model", args->model_path, "Model file (.pca)")->required();
  AddNodeFlags(*edit, graph::PcaEditNodeSpec(), args->edit, {"keep_residual"});
  edit->add_flag("--drop-residual", args->drop_residual,
                 "Rebuild the motion from the model only (default keeps the detail the model does not explain)");
  AddImportFlags(*edit, args->import);
  AddExportFlags(*edit, args->export_options);
  edit->footer(
      "Examples:\n"
      "  mocapfill pca edit walk.glb -o proud.glb --model walk.pca --component 1=+2.0 --component 3=-1.0");
  edit->callback([args, &action] { action = [args] { return RunEdit(*args); }; });
}

}  // namespace mocapfill::cli
