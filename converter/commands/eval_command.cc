// mocapfill eval: the leave-one-out evaluation harness: sketches made from ground
// truth clips, filled by each method against a database without the clip's fold, scored,
// printed as a table (or JSON).
#include <cstdio>
#include <memory>
#include <sstream>

#include "converter/commands.h"
#include "converter/commands/eval_report.h"
#include "converter/console.h"
#include "converter/database_arg.h"
#include "converter/exit_codes.h"
#include "converter/node_flags.h"
#include "converter/option_values.h"
#include "formats/mfdb/motion_folder.h"
#include "formats/motion_io.h"
#include "processing/graph/nodes/fill_schema.h"
#include "processing/motion/resample.h"
#include "processing/evaluation/loso.h"
#include "processing/evaluation/scenarios.h"

namespace mocapfill::cli {

namespace {

struct EvalArgs {
  std::vector<std::string> db, against;
  std::string loso = "style";
  std::string scenario;  // empty: --keep and --every
  std::string keep = "Hips,UpperLeg_L,LowerLeg_L,Foot_L,Toes_L,UpperLeg_R,LowerLeg_R,Foot_R,Toes_R";
  int every = 8;
  std::string methods = "mean,nn,fragment,hierarchical";
  std::string folds, contents, save_sketches;
  bool json = false;
  bool by_fold = false;
  std::string split = "both";
  bool split_given = false;  // --split on the command line (it has no meaning with --against)
  std::string feet = "plant";  // as fill does
  bool mirror = DatabaseOptions{}.mirror;  // the fold databases'; test clips are never mirrored
  NodeFlags flags;  // the fill methods' options (graph/nodes/fill_schema.h), except the method
};

// The fill methods' options as a node type, whose schema gives eval its fill flags (--methods
// replaces the single method).
graph::NodeTypeSpec FillMethodSpec() {
  graph::NodeTypeSpec spec;
  spec.type = "fill";
  spec.options = graph::FillMethodOptionSpecs();
  return spec;
}

Result<std::vector<LabeledClip>> LoadClips(const std::vector<std::string>& paths) {
  ASSIGN_OR_RETURN(const std::vector<std::string> files, ListMotionFiles(paths));
  Progress progress("loading", files.size());
  ASSIGN_OR_RETURN(std::vector<LabeledScene> scenes,
                   ImportMotionFiles(files, ImportOptions{}, 0, [&progress] { progress.Advance(); }));
  std::vector<LabeledClip> clips;
  for (LabeledScene& s : scenes)
    for (MotionClip& clip : s.scene.clips) clips.push_back({s.scene.skeleton, std::move(clip), s.labels});
  return clips;
}

bool Selected(const std::vector<std::string>& list, const ClipLabels& labels, const std::string& key) {
  const auto it = labels.find(key);
  return list.empty() || (it != labels.end() && std::find(list.begin(), list.end(), it->second) != list.end());
}

// Writes every selected clip's sketch as <name>.sketch.glb (keys recorded) and as
// <name>.sketch.bvh sampled at the key rate (a baked sketch: fill it with --keep).
Status SaveSketches(const std::vector<LabeledClip>& clips, const EvaluationOptions& options, const std::string& dir) {
  for (const LabeledClip& c : clips) {
    if (!Selected(options.only_folds, c.labels, options.fold_label) || !Selected(options.only_contents, c.labels, "content"))
      continue;
    ASSIGN_OR_RETURN(MotionClip sketch, MakeSketch(c.skeleton, c.clip, options.sketch));
    Scene scene;
    scene.skeleton = c.skeleton;
    scene.source.format = "bvh";
    scene.source.unit_name = "cm";
    scene.source.unit_scale_to_m = 0.01;
    scene.clips = {sketch};
    const std::string stem = dir + "/" + c.clip.name + ".sketch";
    RETURN_IF_ERROR(ExportFile(scene, stem + ".glb"));
    ResampleOptions resample;
    resample.rate_hz = c.clip.sample_rate_hz / options.sketch.key_every_frames;
    resample.translation = TranslationInterpolation::kLinear;
    ASSIGN_OR_RETURN(scene.clips[0], ResampleClip(sketch, resample));
    RETURN_IF_ERROR(ExportFile(scene, stem + ".bvh"));
  }
  return OkStatus();
}

int RunEval(EvalArgs& args) {
  EvaluationOptions options;
  options.fold_label = args.loso;
  options.sketch.keep_joints = SplitList(args.keep);
  options.sketch.key_every_frames = args.every;
  if (!args.scenario.empty()) {
    Result<SketchScenario> scenario = FindSketchScenario(args.scenario);
    if (!scenario.ok()) {
      PrintError(scenario.status().message());
      return kExitUsage;
    }
    options.sketch = scenario->sketch;
    args.keep.clear();
    for (const std::string& joint : scenario->sketch.keep_joints) args.keep += (args.keep.empty() ? "" : ",") + joint;
    args.every = scenario->sketch.key_every_frames;
  }
  options.only_folds = SplitList(args.folds);
  options.only_contents = SplitList(args.contents);
  options.plant_feet = args.feet == "plant";
  Result<Split> split = ParseSplit(args.split);
  if (!split.ok()) {
    PrintError(split.status().message());
    return kExitUsage;
  }
  // The halves are leave-one-out folds; a fixed database has none, so --against runs unsplit.
  if (!args.against.empty() && args.split_given) {
    PrintError("--split: not used with --against (a fixed database has no folds to split)");
    return kExitUsage;
  }
  options.split = args.against.empty() ? *split : Split::kNone;
  options.database.mirror = args.mirror;
  const graph::NodeTypeSpec spec = FillMethodSpec();
  Result<graph::NodeOptions> node_options = NodeOptionsFromFlags(spec, args.flags);
  Result<FillOptions> fill = node_options.ok() ? graph::FillOptionsFrom(*node_options, FlagLabel(spec))
                                               : Result<FillOptions>(node_options.status());
  Status flags = fill.status();
  for (const std::string& name : SplitList(args.methods)) {
    Result<FillMethod> method = ParseFillMethod(name);
    if (!method.ok()) flags = method.status();
    if (!flags.ok()) break;
    NamedMethod named{name, *fill};
    named.options.method = *method;
    options.methods.push_back(named);
  }
  if (flags.ok()) flags = options.Validate();
  if (!flags.ok()) {
    PrintError(flags.message());
    return kExitUsage;
  }
  Result<std::vector<LabeledClip>> clips = LoadClips(args.db);
  if (!clips.ok()) {
    PrintError(clips.status().message());
    return ExitCodeFor(clips.status(), Stage::kInput);
  }
  Result<std::vector<LabeledClip>> against = std::vector<LabeledClip>{};
  if (!args.against.empty()) against = LoadClips(args.against);
  if (!against.ok()) {
    PrintError(against.status().message());
    return ExitCodeFor(against.status(), Stage::kInput);
  }
  if (!args.save_sketches.empty()) {
    const Status saved = SaveSketches(*clips, options, args.save_sketches);
    if (!saved.ok()) return Fail(saved, Stage::kOutput);
    return kExitOk;
  }
  std::unique_ptr<Progress> progress;  // drawn on a terminal only
  options.on_clip_done = [&progress](int done, int total) {
    if (!progress) progress = std::make_unique<Progress>("scoring", total);
    progress->Advance();
  };
  Result<EvaluationResult> result =
      args.against.empty() ? RunLeaveOneOut(*clips, options) : RunAgainstDatabase(*clips, *against, options);
  progress.reset();
  if (!result.ok()) {
    PrintError(result.status().message());
    return ExitCodeFor(result.status(), Stage::kProcessing);
  }
  EvalReportContext context;
  context.loso = args.loso;
  context.against = args.against;
  context.scenario = args.scenario;
  context.keep = args.keep;
  context.every = args.every;
  context.split = options.split;
  context.bootstrap = options.bootstrap;
  context.default_method = FillMethodName(FillOptions{}.method);
  context.by_fold = args.by_fold;
  if (args.json) {
    PrintEvalJson(*result, context);
  } else {
    PrintEvalTable(*result, context);
  }
  return kExitOk;
}

}  // namespace

void AddEvalCommand(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<EvalArgs>();
  CLI::App* command = app.add_subcommand(
      "eval", "Score fill methods leave-one-out: sketches made from ground-truth clips, filled, compared");
  command->add_option("--db", args->db, "Motion files or folders of the evaluation set (BVH, glTF, FBX)")
      ->required();
  command->add_option("--loso", args->loso, "Clip label whose values form the folds (leave-one-out)")
      ->capture_default_str();
  command->add_option("--against", args->against,
                      "Motion files or folders of a fixed database: every --db clip is tested against it "
                      "(no leave-one-out)");
  std::string scenarios;
  for (const SketchScenario& s : SketchScenarios()) scenarios += "\n  " + s.name + ": " + s.description;
  command->add_option("--scenario", args->scenario,
                      "A named sketch (replaces --keep and --every):" + scenarios);
  command->add_option("--keep", args->keep, "Joints kept in the sketches (comma-separated)")->capture_default_str();
  command->add_option("--every", args->every, "Key spacing of the sketches, frames")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  command->add_option("--methods", args->methods, "Methods to score: mean, nn, fragment, hierarchical, pca, hybrid "
                                                  "(PCA models are built from each fold's database only)")
      ->capture_default_str();
  CLI::Option* split = command->add_option("--split", args->split,
                      "Split-half protocol: the fold values sorted by name and dealt alternately into a tuning "
                      "half (leave-one-out inside itself) and a reporting half (leave-one-out against all other "
                      "folds); tuning, reporting, both (both halves, one table each) or none (plain "
                      "leave-one-out over every fold). Not with --against")
      ->capture_default_str();
  command->add_flag("--by-fold", args->by_fold,
                    "Also print every (fold, category) cell: each method's mean and its difference to mean");
  command->add_option("--folds", args->folds, "Only these folds (comma-separated label values)");
  command->add_option("--contents", args->contents, "Only test clips with these contents (comma-separated)");
  command->add_flag("--json", args->json,
                    "Print JSON (summary with intervals, fold cells, per clip) instead of the table");
  command->add_option("--feet", args->feet, "plant: hold the feet where they touch the ground (as fill does); free: leave them")
      ->check(CLI::IsMember({"plant", "free"}))
      ->capture_default_str();
  AddMirrorFlag(*command, args->mirror);
  command->add_option("--save-sketches", args->save_sketches,
                      "Only write the selected clips' sketches (.sketch.glb, and .sketch.bvh at the key rate) to DIR");
  AddNodeFlags(*command, FillMethodSpec(), args->flags, {"method"});
  command->footer(
      "Example:\n"
      "  mocapfill eval --db ../shared/data/bandai-namco-1/data --loso style --methods mean,hierarchical \\\n"
      "      --feet plant --split both --by-fold\n"
      "  mocapfill eval --db ../shared/data/bandai-namco-1/data --loso style --every 8 \\\n"
      "      --methods mean,nn,fragment,hierarchical --json > eval.json\n"
      "  mocapfill eval --db ../shared/data/bandai-namco-1/data --loso style --every 8 \\\n"
      "      --methods hierarchical,pca,hybrid --contents walk,run\n"
      "  mocapfill eval --db ../shared/data/bandai-namco-1/data --contents dance-short,kick,punch \\\n"
      "      --against fixtures/default_db --methods mean,hierarchical\n"
      "  mocapfill eval --db ../shared/data/bandai-namco-1/data --loso style --scenario upper-body \\\n"
      "      --methods mean,hierarchical");
  command->callback([args, split, &action] {
    args->split_given = split->count() > 0;
    action = [args] { return RunEval(*args); };
  });
}

}  // namespace mocapfill::cli
