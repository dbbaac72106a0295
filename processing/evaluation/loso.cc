#include "processing/evaluation/loso.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <optional>
#include <set>

#include "processing/fill/fill_engine.h"
#include "processing/fill/synthesized_contacts.h"
#include "processing/retargeting/rig_mapping.h"
#include "processing/synthesis/coverage.h"

namespace mocapfill {

namespace {

std::string Label(const LabeledClip& c, const std::string& key) {
  const auto it = c.labels.find(key);
  return it == c.labels.end() ? "" : it->second;
}

bool Contains(const std::vector<std::string>& list, const std::string& value) {
  return std::find(list.begin(), list.end(), value) != list.end();
}

Result<MotionDatabase> BuildDatabase(const std::vector<LabeledClip>& clips, const std::vector<int>& indices,
                                     const EvaluationOptions& options) {
  MotionDatabaseBuilder builder(options.database);
  for (int i : indices) RETURN_IF_ERROR(builder.Add(clips[i].skeleton, clips[i].clip, clips[i].labels));
  return builder.Build();
}

// Coverage figures of one fill: the median unexplained share of its fragments and the share
// of frames inside poorly covered stretches (0 and 0 where coverage is not measured).
void CoverageFigures(const CoverageReport& coverage, int frames, ClipScore& score) {
  score.coverage_median_unexplained = MedianUnexplained(coverage);
  int poor = 0;
  for (const PoorlyCoveredStretch& p : coverage.poor) poor += p.last_frame - p.first_frame + 1;
  score.poorly_covered_share = frames > 0 ? std::min(1.0, double(poor) / frames) : 0.0;
}

// Scores the clips `tests` of `fold` (of the half `half`) against `db`.
Status ScoreClips(const std::vector<LabeledClip>& clips, const std::vector<int>& tests, const std::string& fold,
                  const std::string& half, const MotionDatabase& db, const EvaluationOptions& options, int total,
                  EvaluationResult& result) {
  FillEngine engine(db);
  // The database's legs for planting, found once per fold (every clip's sketch is on its rig).
  std::optional<RigMapping> mapping;
  if (options.plant_feet) {
    ASSIGN_OR_RETURN(RigMapping found, MapHumanoid(db.skeleton(), {}));
    mapping = std::move(found);
  }
  for (int index : tests) {
    const LabeledClip& c = clips[index];
    const std::string content = Label(c, "content");
    if (!options.only_contents.empty() && !Contains(options.only_contents, content)) continue;
    ASSIGN_OR_RETURN(const MotionClip sketch, MakeSketch(c.skeleton, c.clip, options.sketch));
    const std::vector<LegForPlanting> legs = mapping ? LegsToPlant(*mapping, sketch) : std::vector<LegForPlanting>{};
    for (const NamedMethod& method : options.methods) {
      const auto start = std::chrono::steady_clock::now();
      Result<FillResult> filled = engine.Fill(sketch, method.options);
      if (filled.ok() && options.plant_feet) {
        std::vector<LegForPlanting> planted = legs;
        GiveSynthesizedContacts(filled->report, db.skeleton(), filled->clip, *mapping, filled->clip, planted);
        PlantFeet(db.skeleton(), planted, options.feet, filled->clip);
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!filled.ok()) return filled.status().WithContext("clip '" + c.clip.name + "', method " + method.name);
      ASSIGN_OR_RETURN(FillMetrics metrics, ScoreFill(c.skeleton, c.clip, sketch, filled->clip, db.root_joint()));
      ClipScore score{c.clip.name, fold,
                      Contains(options.locomotion_contents, content) ? "locomotion" : "gestures",
                      method.name, metrics, seconds, seconds / std::max(1e-9, c.clip.duration_s())};
      CoverageFigures(filled->report.coverage, sketch.num_frames, score);
      score.half = half;
      result.scores.push_back(score);
    }
    if (options.on_clip_done) {
      std::set<std::string> done;
      for (const ClipScore& s : result.scores) done.insert(s.clip);
      options.on_clip_done(static_cast<int>(done.size()), total);
    }
  }
  return OkStatus();
}

int CountTested(const std::vector<LabeledClip>& clips, const std::vector<int>& tests,
                const EvaluationOptions& options) {
  int total = 0;
  for (int i : tests)
    if (options.only_contents.empty() || Contains(options.only_contents, Label(clips[i], "content"))) ++total;
  return total;
}

std::vector<int> AllIndices(size_t n) {
  std::vector<int> out(n);
  for (size_t i = 0; i < n; ++i) out[i] = static_cast<int>(i);
  return out;
}

void SummariseInto(const EvaluationOptions& options, EvaluationResult& result) {
  result.summary = Summarise(result.scores, options.methods, options.bootstrap);
  result.fold_cells = SummariseFolds(result.scores, options.methods);
  result.above_mean = CountAboveMean(result.fold_cells);
}

}  // namespace

Status EvaluationOptions::Validate() const {
  RETURN_IF_ERROR(sketch.Validate());
  if (fold_label.empty()) return InvalidArgument("fold_label: must name a clip label, e.g. style");
  if (methods.empty()) return InvalidArgument("methods: at least one method is needed");
  for (const NamedMethod& m : methods) RETURN_IF_ERROR(m.options.Validate().WithContext("method " + m.name));
  return database.Validate();
}

Result<EvaluationResult> RunLeaveOneOut(const std::vector<LabeledClip>& clips, const EvaluationOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  if (clips.size() < 2) return InvalidArgument("leave-one-out needs at least two clips");
  std::vector<ClipLabels> labels;
  std::vector<std::string> values;
  for (const LabeledClip& c : clips) {
    const std::string fold = Label(c, options.fold_label);
    if (fold.empty()) return InvalidData("clip '" + c.clip.name + "' has no '" + options.fold_label + "' label");
    labels.push_back(c.labels);
    values.push_back(fold);
  }
  ASSIGN_OR_RETURN(const std::vector<PlannedFold> plan,
                   PlanFolds(labels, {options.fold_label, options.split, options.only_folds}));
  int total = 0;
  for (const PlannedFold& fold : plan) total += CountTested(clips, fold.tests, options);
  EvaluationResult result;
  result.halves = SplitFoldValues(values);
  for (const PlannedFold& fold : plan) {
    Status scored = [&]() -> Status {
      ASSIGN_OR_RETURN(const MotionDatabase db, BuildDatabase(clips, fold.database, options));
      return ScoreClips(clips, fold.tests, fold.fold, fold.half, db, options, total, result);
    }();
    RETURN_IF_ERROR(scored.WithContext("fold '" + fold.fold + "'"));
    ++result.folds;
  }
  SummariseInto(options, result);
  return result;
}

Result<EvaluationResult> RunAgainstDatabase(const std::vector<LabeledClip>& tests,
                                            const std::vector<LabeledClip>& database, const EvaluationOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  if (tests.empty()) return InvalidArgument("no clip to test");
  if (database.empty()) return InvalidArgument("the database has no clip");
  ASSIGN_OR_RETURN(const MotionDatabase db, BuildDatabase(database, AllIndices(database.size()), options));
  EvaluationResult result;
  const std::vector<int> all = AllIndices(tests.size());
  RETURN_IF_ERROR(ScoreClips(tests, all, "against", kNoHalf, db, options, CountTested(tests, all, options), result));
  result.folds = 1;
  SummariseInto(options, result);
  return result;
}

}  // namespace mocapfill
