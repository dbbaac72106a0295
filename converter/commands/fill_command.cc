// mocapfill fill: completes a sketch's missing joints from a motion capture database and writes
// the sketch's asset with a complete animation, plus an optional JSON report (issue #4).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/database_arg.h"
#include "converter/exit_codes.h"
#include "converter/export_flags.h"
#include "converter/fill_flags.h"
#include "converter/import_flags.h"
#include "converter/option_values.h"
#include "formats/file_io.h"
#include "formats/motion_io.h"
#include "formats/pca/pca_file.h"
#include "processing/retargeting/rig_mapping.h"
#include "processing/sketch_fill/sketch_fill.h"
#include "processing/synthesis/coverage.h"

namespace mocapfill::cli {

namespace {

struct FillArgs {
  std::string input, output, report, map, method = "hierarchical", synthesize, keep, pca, rest = "auto";
  std::string position_keys, feet = "plant";
  std::vector<std::string> db;
  ImportOptions import;
  ExportOptions export_options;
  FillOptions fill;
  FillFlagText text;
};

// --map: inline JSON (starting with '{') or a JSON file.
Result<std::map<std::string, std::string>> ReadMapArg(const std::string& arg) {
  if (arg.empty()) return std::map<std::string, std::string>{};
  const size_t first = arg.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && arg[first] == '{') return ParseRigMapJson(arg, "--map");
  ASSIGN_OR_RETURN(const std::string bytes, ReadFileBytes(arg));
  return ParseRigMapJson(bytes, arg);
}

// Frames of the fill (at the database rate) as seconds of the sketch; a takes ratio that
// could not be measured (a one-clip database) as null.
nlohmann::ordered_json CoverageJson(const CoverageReport& c, double rate_hz) {
  const auto ratio = [](double r) { return r < 0.0 ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r); };
  nlohmann::ordered_json out;
  out["measured"] = c.measured;
  out["poor_share"] = c.poor_share;
  out["none_share"] = c.none_share;
  out["texture_poor_share"] = c.texture_poor_share;
  out["texture_none_share"] = c.texture_none_share;
  out["takes_distance"] = c.reference_distance;
  out["prior"] = c.prior.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(c.prior);
  nlohmann::ordered_json poor = nlohmann::ordered_json::array();
  for (const PoorlyCoveredStretch& p : c.poor)
    poor.push_back({{"from_s", p.first_frame / rate_hz}, {"to_s", p.last_frame / rate_hz},
                    {"worst_unexplained", p.worst_unexplained}, {"worst_takes_ratio", ratio(p.worst_takes_ratio)},
                    {"max_prior_weight", p.max_prior_weight}});
  out["poorly_covered"] = poor;
  nlohmann::ordered_json fragments = nlohmann::ordered_json::array();
  for (const FragmentCoverage& f : c.fragments)
    fragments.push_back({{"from_s", f.first_frame / rate_hz}, {"to_s", f.last_frame / rate_hz},
                         {"distance", f.distance}, {"unexplained", f.unexplained},
                         {"takes_ratio", ratio(f.takes_ratio)}, {"prior_weight", f.prior_weight},
                         {"texture_weight", f.texture_weight}});
  out["fragments"] = fragments;
  return out;
}

nlohmann::ordered_json ReportJson(const SketchFillResult& result, const std::string& db_name, double load_s) {
  const FillReport& r = result.report;
  nlohmann::ordered_json out;
  out["method"] = r.method;
  out["join"] = r.join;
  out["database"] = db_name;
  out["frames"] = result.scene.clips.front().num_frames;
  out["rate_hz"] = result.output_rate_hz;
  out["uniform"] = result.uniform;
  out["database_rate_hz"] = result.database_rate_hz;
  out["rig"] = {{"family", result.rig.family},
                {"rest", result.rig.rest},
                {"same_as_database", result.rig.same_as_database},
                {"mapped_bones", result.rig.mapped_bones},
                {"warnings", result.rig.warnings}};
  out["key_spacing_frames"] = r.key_spacing_frames;
  out["master_channel"] = r.master_channel;
  out["fragment_band"] = r.fragment_band;
  out["sketch_fragments"] = r.sketch_fragments;
  out["seams"] = r.seams;
  // Measured on the file written, at the sketch's exact key times.
  out["key_error_mean_deg"] = result.key_error_mean_deg;
  out["key_error_max_deg"] = result.key_error_max_deg;
  out["root_key_error_max_m"] = result.translation_key_error_max_m;
  out["max_frame_jump_deg"] = result.max_frame_jump_deg;
  nlohmann::ordered_json contacts = nlohmann::ordered_json::array();
  for (const FootContact& c : result.feet.contacts)
    contacts.push_back({{"foot", c.side}, {"from_s", c.start_s}, {"to_s", c.end_s},
                        {"max_correction_m", c.max_correction_m}});
  out["feet"] = {{"contacts", contacts}, {"frames_held", result.feet.frames_held},
                 {"max_correction_m", result.feet.max_correction_m}};
  nlohmann::ordered_json joints = nlohmann::ordered_json::array();
  for (const JointFillInfo& j : result.joints)
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
  out["coverage"] = CoverageJson(r.coverage, result.database_rate_hz);
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
  out["warnings"] = result.warnings;
  nlohmann::ordered_json stages = nlohmann::ordered_json::object();
  stages["load_database"] = load_s;
  for (const StageTime& s : r.stages) stages[s.stage] = s.seconds;
  out["stage_seconds"] = stages;
  return out;
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
  if (!result.feet.contacts.empty())
    std::fprintf(stderr, "  feet: %zu contacts held between keys, %d leg-frames, largest correction %.1f cm\n",
                 result.feet.contacts.size(), result.feet.frames_held, 100.0 * result.feet.max_correction_m);
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
  Status flags = ApplyFillFlagText(args.text, args.fill);
  if (flags.ok()) {
    Result<FillMethod> method = ParseFillMethod(args.method);
    flags = method.status();
    if (method.ok()) args.fill.method = *method;
  }
  if (flags.ok()) flags = args.fill.Validate();
  SketchFillOptions options;
  options.fill = args.fill;
  if (flags.ok()) {
    Result<RestSource> rest = ParseRestSource(args.rest);
    flags = rest.status();
    if (rest.ok()) options.rest = *rest;
  }
  if (!flags.ok()) return Fail(flags, Stage::kProcessing);
  if (!IsExportExtension(args.output))
    return Fail(InvalidArgument(args.output + ": output must end in .gltf, .glb or .bvh"), Stage::kOutput);
  if (IsSameFile(args.input, args.output)) return Fail(IoError(args.output + ": refusing to overwrite the input"), Stage::kOutput);
  Result<std::map<std::string, std::string>> map = ReadMapArg(args.map);
  if (!map.ok()) return Fail(map.status(), Stage::kInput);
  options.map = *map;
  options.output_rate_hz = args.import.rate_hz;
  options.keep = SplitList(args.keep);
  options.synthesize = SplitList(args.synthesize);
  options.position_keys = SplitList(args.position_keys);
  options.plant_feet = args.feet == "plant";
  Result<Scene> scene = ImportFile(args.input, args.import);
  if (!scene.ok()) return Fail(scene.status(), Stage::kInput);
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
    return Fail(filled.status().WithContext(args.input), stage);
  }
  for (const std::string& w : filled->warnings) PrintWarning(args.input + ": " + w);
  const Status written = ExportFile(filled->scene, args.output, args.export_options);
  if (!written.ok()) return Fail(written, Stage::kOutput);
  const Status measured = MeasureWrittenKeys(args.output, *scene, *filled);
  if (!measured.ok()) return Fail(measured, Stage::kProcessing);
  const std::string db_name = args.db.empty() ? "default" : args.db[0];
  if (!args.report.empty()) {
    const Status report = WriteFileAtomic(args.report, ReportJson(*filled, db_name, load_s).dump(2) + "\n");
    if (!report.ok()) return Fail(report, Stage::kOutput);
  }
  PrintSummary(*filled);
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
  command->add_option("--map", args->map,
                      "Rig map overrides, inline JSON or a JSON file: {\"sketch joint\": \"canonical bone or database "
                      "joint\", ...} (\"\" leaves a joint unmapped); the rest is mapped automatically");
  command->add_option("--rest", args->rest, "The sketch rig's rest pose: auto, bind, zero or first-frame")
      ->check(CLI::IsMember({"auto", "bind", "zero", "first-frame"}))
      ->capture_default_str();
  command->add_option("--position-keys", args->position_keys,
                      "Joints whose translation keys are world-space position targets (comma-separated)");
  command->add_option("--feet", args->feet,
                      "plant: a foot standing low and still at two consecutive keys is held there in between "
                      "(leg IK; keys stay exact); free: legs as filled")
      ->check(CLI::IsMember({"plant", "free"}))
      ->capture_default_str();
  command->add_option("--synthesize", args->synthesize, "Joints to synthesise even if keyed (comma-separated)");
  command->add_option("--keep", args->keep, "Only these joints are keyed; every other joint is synthesised");
  AddFillFlags(*command, args->fill, args->text);
  AddPcaMethodFlags(*command, args->fill, args->text);
  AddImportFlags(*command, args->import);
  AddExportFlags(*command, args->export_options);
  command->footer(
      "Examples:\n"
      "  mocapfill fill sketch.glb -o enriched.glb --report fill.json\n"
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
