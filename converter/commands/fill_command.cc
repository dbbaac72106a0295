// mocapfill fill: completes a sketch's missing joints from a motion capture database and writes
// the sketch's asset with a complete animation, plus an optional JSON report (issue #4).
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/database_arg.h"
#include "converter/exit_codes.h"
#include "converter/fill_flags.h"
#include "converter/import_flags.h"
#include "formats/file_io.h"
#include "formats/motion_io.h"
#include "formats/pca/pca_file.h"
#include "processing/motion/resample.h"
#include "processing/synthesis/fill.h"
#include "processing/synthesis/skeleton_map.h"

namespace mocapfill::cli {

namespace {

struct FillArgs {
  std::string input, output, report, map, method = "hierarchical", synthesize, keep, pca;
  std::vector<std::string> db;
  ImportOptions import;
  FillOptions fill;
  FillFlagText text;
};

struct Failure {
  Status status;
  Stage stage;
};

std::vector<std::string> SplitList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

Result<std::map<std::string, std::string>> ReadNameMap(const std::string& path) {
  std::map<std::string, std::string> map;
  if (path.empty()) return map;
  ASSIGN_OR_RETURN(const std::string bytes, ReadFileBytes(path));
  const nlohmann::json json = nlohmann::json::parse(bytes, nullptr, false);
  if (json.is_discarded() || !json.is_object())
    return InvalidData(path + ": expected a JSON object {\"sketch joint\": \"database joint\", ...}");
  for (const auto& [key, value] : json.items()) {
    if (!value.is_string()) return InvalidData(path + ": value of '" + key + "' must be a joint name string");
    map[key] = value.get<std::string>();
  }
  return map;
}

// --synthesize drops the keys of the listed joints; --keep drops the keys of every other joint.
Status ApplyKeyOverrides(const FillArgs& args, const Skeleton& skeleton, MotionClip& clip) {
  const std::vector<std::string> synth = SplitList(args.synthesize), keep = SplitList(args.keep);
  for (const auto* list : {&synth, &keep})
    for (const std::string& name : *list)
      if (!skeleton.Find(name)) return InvalidArgument("joint '" + name + "' is not in the sketch");
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const std::string& name = skeleton.name(j);
    const bool listed_synth = std::find(synth.begin(), synth.end(), name) != synth.end();
    const bool listed_keep = std::find(keep.begin(), keep.end(), name) != keep.end();
    if (listed_synth || (!keep.empty() && !listed_keep)) clip.keys[j] = JointKeys{};
  }
  return OkStatus();
}

nlohmann::ordered_json ReportJson(const FillReport& r, const std::string& db_name, double load_s) {
  nlohmann::ordered_json out;
  out["method"] = r.method;
  out["join"] = r.join;
  out["database"] = db_name;
  out["frames"] = r.frames;
  out["rate_hz"] = r.rate_hz;
  out["key_spacing_frames"] = r.key_spacing_frames;
  out["master_channel"] = r.master_channel;
  out["fragment_band"] = r.fragment_band;
  out["sketch_fragments"] = r.sketch_fragments;
  out["seams"] = r.seams;
  out["key_error_mean_deg"] = r.key_error_mean_deg;
  out["key_error_max_deg"] = r.key_error_max_deg;
  nlohmann::ordered_json joints = nlohmann::ordered_json::array();
  for (const JointFillInfo& j : r.joints)
    joints.push_back({{"joint", j.name}, {"kind", j.kind}, {"keys", j.keys},
                      {"key_error_mean_deg", j.key_error_mean_deg}, {"key_error_max_deg", j.key_error_max_deg}});
  out["joints"] = joints;
  nlohmann::ordered_json fragments = nlohmann::ordered_json::array();
  for (const FragmentSource& f : r.fragments)
    fragments.push_back({{"group", f.group}, {"frames", {f.first_frame, f.last_frame}}, {"clip", f.clip},
                         {"clip_frames", {f.clip_first_frame, f.clip_last_frame}}, {"distance", f.distance},
                         {"blended", f.blended}});
  out["fragments"] = fragments;
  out["group_order"] = r.group_order;
  if (!r.pca_model_source.empty())
    out["pca_model"] = {{"source", r.pca_model_source}, {"components", r.pca_components}};
  if (r.has_solver) {
    const SolverReport& s = r.solver;
    out["pca_solver"] = {{"termination", s.termination_type}, {"converged", s.converged},
                         {"iterations", s.iterations},        {"initial_cost", s.initial_cost},
                         {"final_cost", s.final_cost},        {"linear_solver", s.linear_solver},
                         {"parameters", s.num_parameters},    {"residuals", s.num_residuals},
                         {"solve_seconds", s.solve_time_s},   {"message", s.message}};
  }
  nlohmann::ordered_json stages = nlohmann::ordered_json::object();
  stages["load_database"] = load_s;
  for (const StageTime& s : r.stages) stages[s.stage] = s.seconds;
  out["stage_seconds"] = stages;
  return out;
}

void PrintSummary(const FillReport& r) {
  if (IsQuiet()) return;
  int keyed = 0, synthesized = 0, textured = 0;
  for (const JointFillInfo& j : r.joints) (j.kind == "keyed" ? keyed : j.kind == "textured" ? textured : synthesized)++;
  std::fprintf(stderr, "fill: %s (%s), %d frames at %.0f Hz, keys every %d frames\n", r.method.c_str(), r.join.c_str(),
               r.frames, r.rate_hz, r.key_spacing_frames);
  std::fprintf(stderr, "  joints: %d keyed, %d textured, %d synthesized; %d fragments, %d seams\n", keyed, textured,
               synthesized, r.sketch_fragments, r.seams);
  std::fprintf(stderr, "  keys: mean error %.4f deg, max %.4f deg\n", r.key_error_mean_deg, r.key_error_max_deg);
  std::fprintf(stderr, "  time:");
  for (const StageTime& s : r.stages) std::fprintf(stderr, " %s %.1f ms", s.stage.c_str(), 1000.0 * s.seconds);
  std::fprintf(stderr, "\n");
  if (!r.pca_model_source.empty())
    std::fprintf(stderr, "  pca model: %s, %d components\n", r.pca_model_source.c_str(), r.pca_components);
  if (r.has_solver)
    std::fprintf(stderr, "  pca fit: %s after %d iterations, cost %.4g -> %.4g\n", r.solver.termination_type.c_str(),
                 r.solver.iterations, r.solver.initial_cost, r.solver.final_cost);
}

Result<Scene> LoadSketch(const FillArgs& args) {
  ASSIGN_OR_RETURN(Scene scene, ImportFile(args.input, args.import));
  if (scene.clips.empty()) return InvalidData(args.input + ": the sketch has no animation");
  if (scene.clips.size() > 1) scene.clips.resize(1);  // the first animation is the sketch
  if (scene.clips[0].num_frames < 1) return InvalidData(args.input + ": the sketch's animation is empty");
  RETURN_IF_ERROR(ApplyKeyOverrides(args, scene.skeleton, scene.clips[0]));
  bool any = false;
  for (const JointKeys& k : scene.clips[0].keys) any = any || !k.empty();
  if (!any) return InvalidData(args.input + ": the sketch has no keyed joint (nothing to fill from)");
  return scene;
}

int Fail(const Status& status, Stage stage) {
  PrintError(status.message());
  return ExitCodeFor(status, stage);
}

int RunFill(FillArgs& args) {
  Status flags = ApplyFillFlagText(args.text, args.fill);
  if (flags.ok()) {
    Result<FillMethod> method = ParseFillMethod(args.method);
    flags = method.status();
    if (method.ok()) args.fill.method = *method;
  }
  if (flags.ok()) flags = args.fill.Validate();
  if (!flags.ok()) return Fail(flags, Stage::kProcessing);
  if (!IsExportExtension(args.output))
    return Fail(InvalidArgument(args.output + ": output must end in .gltf, .glb or .bvh"), Stage::kOutput);
  if (IsSameFile(args.input, args.output)) return Fail(IoError(args.output + ": refusing to overwrite the input"), Stage::kOutput);
  Result<std::map<std::string, std::string>> map = ReadNameMap(args.map);
  if (!map.ok()) return Fail(map.status(), Stage::kInput);
  Result<Scene> scene = LoadSketch(args);
  if (!scene.ok()) return Fail(scene.status(), Stage::kInput);
  const auto load_start = std::chrono::steady_clock::now();
  Result<MotionDatabase> db = LoadDatabase(args.db);
  if (!db.ok()) return Fail(db.status(), Stage::kInput);
  const double load_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - load_start).count();
  Result<SkeletonMapping> mapping = MapSkeletons(scene->skeleton, scene->clips[0], db->skeleton(), *map);
  if (!mapping.ok()) return Fail(mapping.status().WithContext(args.input), Stage::kInput);
  for (const std::string& w : mapping->warnings) PrintWarning(args.input + ": " + w);
  ResampleOptions resample;
  resample.rate_hz = db->rate_hz();
  Result<MotionClip> sketch = ResampleClip(scene->clips[0], resample);
  if (!sketch.ok()) return Fail(sketch.status().WithContext(args.input), Stage::kInput);
  Result<PcaModel> model = PcaModel{};
  if (!args.pca.empty()) {
    model = ReadPcaModel(args.pca);
    if (!model.ok()) return Fail(model.status(), Stage::kInput);
  }
  FillEngine engine(*db);
  if (!args.pca.empty()) engine.SetPcaModel(&*model);
  Result<FillResult> filled = engine.Fill(ToDatabaseClip(*mapping, db->skeleton(), *sketch), args.fill);
  if (!filled.ok()) return Fail(filled.status().WithContext(args.input), Stage::kProcessing);
  Scene out = std::move(*scene);
  out.clips = {ToSketchClip(*mapping, filled->clip, *sketch, db->root_joint())};
  const Status written = ExportFile(out, args.output);
  if (!written.ok()) return Fail(written, Stage::kOutput);
  const std::string db_name = args.db.empty() ? "default" : args.db[0];
  if (!args.report.empty()) {
    const Status report = WriteFileAtomic(args.report, ReportJson(filled->report, db_name, load_s).dump(2) + "\n");
    if (!report.ok()) return Fail(report, Stage::kOutput);
  }
  PrintSummary(filled->report);
  return kExitOk;
}

}  // namespace

void AddFillCommand(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<FillArgs>();
  CLI::App* command = app.add_subcommand("fill", "Fill the missing joints of a keyframed sketch from a motion database");
  command->add_option("input", args->input, "Sketch (.bvh .gltf .glb .fbx): joints with a channel are keyed")
      ->required();
  command->add_option("-o,--output", args->output, "Output file (.glb .gltf .bvh)")->required();
  command->add_option("--db", args->db, "Database: an .mfdb file or motion files/folders (default: embedded)");
  command->add_option("--method", args->method, "hierarchical, fragment, nn, mean, pca or hybrid")
      ->check(CLI::IsMember({"hierarchical", "fragment", "nn", "mean", "pca", "hybrid"}))
      ->capture_default_str();
  command->add_option("--pca", args->pca,
                      "PCA model (.pca, `mocapfill pca build`) for --method pca|hybrid; default: built in memory "
                      "from the database (time reported as stage pca_model)");
  command->add_option("--report", args->report, "Write a JSON report (joints, fragment sources, seams, key errors, times)");
  command->add_option("--map", args->map, "JSON object renaming sketch joints to database joints");
  command->add_option("--synthesize", args->synthesize, "Joints to synthesise even if keyed (comma-separated)");
  command->add_option("--keep", args->keep, "Only these joints are keyed; every other joint is synthesised");
  AddFillFlags(*command, args->fill, args->text);
  AddPcaMethodFlags(*command, args->fill, args->text);
  AddImportFlags(*command, args->import);
  command->footer(
      "Examples:\n"
      "  mocapfill fill sketch.glb -o enriched.glb --report fill.json\n"
      "  mocapfill fill baked.bvh -o out.glb --keep Hips,UpperLeg_L,LowerLeg_L,Foot_L,UpperLeg_R,LowerLeg_R,Foot_R\n"
      "  mocapfill fill sketch.glb -o out.glb --db ../shared/data/bandai-namco-1/data --method fragment\n"
      "  mocapfill fill sketch.glb -o out.glb --method hybrid --pca walk.pca --report fill.json\n"
      "  mocapfill fill sketch.glb -o out.glb --method hybrid --pca-fit full-pose --dial 1=+1.5");
  command->callback([args, &action] { action = [args] { return RunFill(*args); }; });
}

}  // namespace mocapfill::cli
