// mocapfill fill: completes a sketch's missing joints from a motion capture database and writes
// the sketch's asset with a complete animation, plus an optional JSON report.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>
#include <nlohmann/json.hpp>
#include <sstream>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/database_arg.h"
#include "converter/exit_codes.h"
#include "converter/export_flags.h"
#include "converter/import_flags.h"
#include "converter/node_flags.h"
#include "converter/std_streams.h"
#include "formats/file_io.h"
#include "formats/motion_io.h"
#include "formats/name_map_json.h"
#include "formats/pca/pca_file.h"
#include "library/fill_report_json.h"
#include "processing/graph/nodes/fill_schema.h"
#include "processing/graph/nodes/nodes.h"
#include "processing/retargeting/rig_mapping.h"
#include "processing/sketch_fill/sketch_fill.h"
#include "processing/synthesis/coverage.h"

namespace mocapfill::cli {

namespace {

struct FillArgs {
  std::string input, output, report, map, pca;
  std::string from, format = "glb";  // formats of - (standard input / output)
  bool json = false;
  std::vector<std::string> db;
  ImportOptions import;
  ExportOptions export_options;
  NodeFlags flags;  // the fill node's options (graph/nodes/fill_schema.h)
};

// The fill node's options the verb takes its own way: the rig map as inline JSON or a file
// (--map), the output rate with the import's (--rate).
const std::set<std::string> kOwnWay = {"rename", "rate_hz"};

// --map: inline JSON (starting with '{') or a JSON file.
Result<std::map<std::string, std::string>> ReadMapArg(const std::string& arg) {
  if (arg.empty()) return std::map<std::string, std::string>{};
  return ReadNameMap(arg, "--map", kRigMapShape);
}

void PrintSummary(const SketchFillResult& result) {
  if (IsQuiet()) return;
  const FillReport& r = result.report;
  int keyed = 0, synthesized = 0, textured = 0, kept = 0;
  for (const JointFillInfo& j : result.joints)
    (j.kind == "keyed" ? keyed : j.kind == "textured" ? textured : j.kind == "kept" ? kept : synthesized)++;
  std::fprintf(stderr, "fill: %s (%s), %d frames at %g Hz%s (filled at %g Hz), keys every %d frames\n",
               r.method.c_str(), r.join.c_str(), result.scene.clips.front().num_frames, result.output_rate_hz,
               result.uniform ? "" : " plus off-grid key times", result.database_rate_hz, r.key_spacing_frames);
  std::fprintf(stderr, "  rig: %s, %d canonical bones mapped, rest %s%s\n", result.rig.family.c_str(),
               result.rig.mapped_bones, result.rig.rest.c_str(),
               result.rig.same_as_database ? " (the database's rig)" : "");
  std::fprintf(stderr, "  joints: %d keyed, %d textured, %d synthesized, %d kept; %d fragments, %d seams\n", keyed,
               textured, synthesized, kept, r.sketch_fragments, r.seams);
  std::fprintf(stderr, "  keys: mean error %.4f deg, max %.4f deg (read back from the output, at the keys' own times)\n",
               result.key_error_mean_deg, result.key_error_max_deg);
  if (!result.feet.contacts.empty()) {
    const auto found_on = [&](const char* source) {
      return std::count_if(result.feet.contacts.begin(), result.feet.contacts.end(),
                           [&](const FootContact& c) { return c.found_on == source; });
    };
    std::fprintf(stderr, "  feet: %zu contacts held (%td where the matched takes stood, %td where the keys have the "
                 "foot still, %td where a key has it stand as the hips pass), %d leg-frames, largest correction "
                 "%.1f cm\n",
                 result.feet.contacts.size(), found_on("takes"), found_on("keys"), found_on("stance"),
                 result.feet.frames_held, 100.0 * result.feet.max_correction_m);
  }
  if (r.coverage.measured && !r.coverage.fragments.empty()) {
    const auto less = [](const FragmentCoverage& a, const FragmentCoverage& b) { return a.unexplained < b.unexplained; };
    const double worst =
        std::max_element(r.coverage.fragments.begin(), r.coverage.fragments.end(), less)->unexplained;
    std::fprintf(stderr, "  coverage: the nearest matches leave %.1f%% (median) and at worst %.1f%% of the keyed "
                 "motion unexplained; %zu poorly covered stretch%s\n",
                 100.0 * MedianUnexplained(r.coverage), 100.0 * worst, r.coverage.poor.size(),
                 r.coverage.poor.size() == 1 ? "" : "es");
  }
  std::fprintf(stderr, "  time:");
  for (const StageTime& s : r.stages) std::fprintf(stderr, " %s %.1f ms", s.stage.c_str(), 1000.0 * s.seconds);
  std::fprintf(stderr, "\n");
  if (!r.pca_model_source.empty())
    std::fprintf(stderr, "  pca model: %s, %d components\n", r.pca_model_source.c_str(), r.pca_components);
  if (r.has_solver)
    std::fprintf(stderr, "  pca fit: %s after %d iterations, cost %.4g -> %.4g\n", r.solver.termination_type.c_str(),
                 r.solver.iterations, r.solver.initial_cost, r.solver.final_cost);
}

// The key errors as the written file holds them: the output read back and evaluated at the
// sketch's exact key times. Replaces the in-memory figures of `result`.
Status MeasureWrittenKeys(const std::string& path, const Scene& sketch, SketchFillResult& result) {
  ASSIGN_OR_RETURN(Scene written, ImportFile(path));
  if (written.clips.empty()) return Internal(path + ": the written file has no animation to check");
  ApplyKeyChecks(CheckKeys(written.skeleton, written.clips.front(), sketch.skeleton, result.keyed_sketch), result);
  return OkStatus();
}

int RunFill(FillArgs& args) {
  const graph::NodeTypeSpec spec = graph::FillNodeSpec();
  Result<graph::NodeOptions> node_options = NodeOptionsFromFlags(spec, args.flags);
  if (!node_options.ok()) return Fail(node_options.status(), Stage::kProcessing);
  Result<SketchFillOptions> checked = graph::SketchFillOptionsFrom(*node_options, FlagLabel(spec));
  if (!checked.ok()) return Fail(checked.status(), Stage::kProcessing);
  SketchFillOptions options = std::move(checked).value();
  if (args.json && IsStdStream(args.output))
    return Fail(InvalidArgument("--json and an output on standard output (-) cannot share it"), Stage::kOutput);
  // "-": standard input spooled to a file, standard output written through one.
  std::optional<TemporaryFile> stdin_file, stdout_file;
  if (IsStdStream(args.input)) {
    Result<TemporaryFile> spooled = SpoolStdin(args.from);
    if (!spooled.ok()) return Fail(spooled.status(), Stage::kInput);
    stdin_file.emplace(std::move(spooled).value());
    args.input = stdin_file->path();
  }
  if (IsStdStream(args.output)) {
    Result<TemporaryFile> temporary = TemporaryFile::Create(args.format);
    if (!temporary.ok()) return Fail(temporary.status(), Stage::kOutput);
    stdout_file.emplace(std::move(temporary).value());
    args.output = stdout_file->path();
  }
  const std::string given_input = stdin_file ? "-" : args.input;
  if (!IsExportExtension(args.output))
    return Fail(InvalidArgument(args.output + ": output must end in .gltf, .glb or .bvh"), Stage::kOutput);
  if (IsSameFile(args.input, args.output)) return Fail(IoError(args.output + ": refusing to overwrite the input"), Stage::kOutput);
  Result<std::map<std::string, std::string>> map = ReadMapArg(args.map);
  if (!map.ok()) return Fail(map.status(), Stage::kInput);
  options.map = *map;
  options.output_rate_hz = args.import.rate_hz;
  Result<Scene> scene = ImportFile(args.input, args.import);
  if (!scene.ok()) return Fail(Status(scene.status().code(), AsGiven(scene.status().message(), args.input)), Stage::kInput);
  if (scene->clips.size() > 1) scene->clips.resize(1);  // the first animation is the sketch
  const auto load_start = std::chrono::steady_clock::now();
  Result<MotionDatabase> db = LoadDatabase(args.db);
  if (!db.ok()) return Fail(db.status(), Stage::kInput);
  const double load_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();
  Result<PcaModel> model = PcaModel{};
  if (!args.pca.empty()) {
    model = ReadPcaModel(args.pca);
    if (!model.ok()) return Fail(model.status(), Stage::kInput);
  }
  Result<SketchFillResult> filled = FillSketch(*scene, *db, options, args.pca.empty() ? nullptr : &*model);
  if (!filled.ok()) {
    const Stage stage = filled.status().code() == ErrorCode::kInvalidData ? Stage::kInput : Stage::kProcessing;
    return Fail(filled.status().WithContext(given_input), stage);
  }
  for (const std::string& w : filled->warnings) PrintWarning(given_input + ": " + w);
  const Status written = ExportFile(filled->scene, args.output, args.export_options);
  if (!written.ok()) return Fail(written, Stage::kOutput);
  const Status measured = MeasureWrittenKeys(args.output, *scene, *filled);
  if (!measured.ok()) return Fail(measured, Stage::kProcessing);
  const std::string db_name = args.db.empty() ? "default" : args.db[0];
  const std::string report = args.report.empty() && !args.json ? "" : FillReportJson(*filled, db_name, load_s);
  if (!args.report.empty()) {
    const Status written_report = WriteFileAtomic(args.report, report + "\n");
    if (!written_report.ok()) return Fail(written_report, Stage::kOutput);
  }
  PrintSummary(*filled);
  if (args.json) std::printf("%s\n", report.c_str());
  if (stdout_file) {
    const Status copied = CopyToStdout(stdout_file->path());
    if (!copied.ok()) return Fail(copied, Stage::kOutput);
  }
  return kExitOk;
}

}  // namespace

void AddFillCommand(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<FillArgs>();
  CLI::App* command = app.add_subcommand("fill", "Fill the missing joints of a keyframed sketch from a motion database");
  command->add_option("input", args->input,
                      "Sketch (.bvh .gltf .glb .fbx; - for standard input, with --from): joints with a channel are keyed")
      ->required();
  command->add_option("-o,--output", args->output, "Output file (.glb .gltf .bvh; - for standard output, in --format)")
      ->required();
  command->add_option("--from", args->from, "Format of a - input (standard input): bvh, gltf, glb or fbx")
      ->check(CLI::IsMember({"bvh", "gltf", "glb", "fbx"}));
  command->add_option("--format", args->format, "Format of a - output (standard output): glb, gltf or bvh")
      ->check(CLI::IsMember({"glb", "gltf", "bvh"}))
      ->capture_default_str();
  command->add_flag("--json", args->json, "Print the report (as --report writes it) on standard output");
  command->add_option("--db", args->db, "Database: an .mfdb file or motion files/folders (default: embedded)");
  command->add_option("--pca", args->pca,
                      "PCA model (.pca, `mocapfill pca build`) for --method pca|hybrid; default: built in memory "
                      "from the database (time reported as stage pca_model)");
  command->add_option("--report", args->report, "Write a JSON report (joints, fragment sources, seams, key errors, times)");
  command->add_option("--map", args->map,
                      "Rig map overrides, inline JSON or a JSON file: {\"sketch joint\": \"canonical bone or database "
                      "joint\", ...} (\"\" leaves a joint unmapped); the rest is mapped automatically");
  AddNodeFlags(*command, graph::FillNodeSpec(), args->flags, kOwnWay);
  AddImportFlags(*command, args->import);
  AddExportFlags(*command, args->export_options);
  command->footer(
      "Examples:\n"
      "  mocapfill fill sketch.glb -o enriched.glb --report fill.json\n"
      "  mocapfill fill sketch.glb -o enriched.glb --json | jq .key_error_max_deg\n"
      "  cat sketch.bvh | mocapfill fill - --from bvh -o - --format glb > enriched.glb\n"
      "  mocapfill fill baked.bvh -o out.glb --keep Hips,UpperLeg_L,LowerLeg_L,Foot_L,UpperLeg_R,LowerLeg_R,Foot_R\n"
      "  mocapfill fill sketch.glb -o out.glb --db ../shared/data/bandai-namco-1/data --method fragment\n"
      "  mocapfill fill sketch.glb -o out.glb --method hybrid --pca walk.pca --report fill.json\n"
      "  mocapfill fill sketch.glb -o out.glb --method hybrid --pca-fit full-pose --dial 1=+1.5\n"
      "  mocapfill fill my_rig_sketch.glb -o out.glb --map '{\"Bip01 L Clavicle\": \"leftShoulder\"}' --rate 60\n"
      "  mocapfill fill ik_sketch.glb -o out.glb --method hybrid --pca-fit full-pose --position-keys LeftFoot,RightFoot\n"
      "\n"
      "The sketch may be on any humanoid rig (see `mocapfill rig show`); the output is that rig at the sketch's\n"
      "own rate, or at --rate HZ, which also sets the grid keyed inputs are read on. Keys are reproduced at their\n"
      "exact times; the reported key error is measured on the file written.");
  command->callback([args, &action] { action = [args] { return RunFill(*args); }; });
}

}  // namespace mocapfill::cli
