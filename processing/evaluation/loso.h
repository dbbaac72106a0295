// Leave-one-out evaluation protocol: clips are grouped into folds by a
// label (leave-one-style-out: --loso style); for each fold a database is built from the
// other folds' clips (with a split, fold_plan.h decides which), every clip of the fold is
// reduced to a sketch, filled by each method and scored against itself. Locomotion and
// gestures are summarised separately, per half (summary.h).
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"
#include "processing/database/motion_database_builder.h"
#include "processing/evaluation/fold_plan.h"
#include "processing/evaluation/metrics.h"
#include "processing/evaluation/sketch_maker.h"
#include "processing/evaluation/summary.h"
#include "processing/fill/fill_options.h"
#include "processing/motion/foot_plant.h"

namespace mocapfill {

struct LabeledClip {
  Skeleton skeleton;
  MotionClip clip;   // every frame keyed (ground truth)
  ClipLabels labels;  // "content", "style", ...
};

struct EvaluationOptions {
  std::string fold_label = "style";  // clips sharing this label's value form one fold
  // Plain leave-one-out by default; the split-half protocol is fold_plan.h's.
  Split split = Split::kNone;
  BootstrapOptions bootstrap;  // the summary's intervals
  SketchSpec sketch;
  std::vector<NamedMethod> methods;
  // Contents reported as locomotion; every other content is a gesture.
  std::vector<std::string> locomotion_contents = {"walk", "walk-back", "walk-left", "walk-right", "run", "dash"};
  std::vector<std::string> only_folds;      // empty = every fold
  std::vector<std::string> only_contents;   // empty = every content is tested
  DatabaseOptions database;
  // Plant the feet between keys after each fill (foot_plant.h), as `fill --feet plant` does.
  bool plant_feet = false;
  FootPlantOptions feet;
  // Called after every scored clip (may be empty): done, total.
  std::function<void(int, int)> on_clip_done;

  Status Validate() const;
};

struct EvaluationResult {
  std::vector<ClipScore> scores;
  std::vector<SummaryRow> summary;  // per half and method: locomotion, gestures, all
  std::vector<FoldCell> fold_cells;
  std::vector<AboveMeanCount> above_mean;
  int folds = 0;       // folds run
  SplitHalves halves;  // of every fold value (empty without leave-one-out)
};

// Runs the protocol: the folds of PlanFolds (options.split), each tested against a database of
// its plan's clips. Every clip must have the first clip's skeleton (joint names and parents)
// and its rate. Errors: invalid options, clips without the fold label, a half too small to
// split, a method failing.
Result<EvaluationResult> RunLeaveOneOut(const std::vector<LabeledClip>& clips, const EvaluationOptions& options);

// Every clip of `tests` (those of options.only_contents) sketched and filled against one
// database built from `database` (no leave-one-out: the fold label is not used; the scores'
// fold is "against"). Errors: invalid options, no test or database clip, a method failing.
Result<EvaluationResult> RunAgainstDatabase(const std::vector<LabeledClip>& tests,
                                            const std::vector<LabeledClip>& database, const EvaluationOptions& options);

}  // namespace mocapfill
