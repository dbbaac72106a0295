#include "processing/evaluation/loso.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <set>

#include "processing/fill/fill_engine.h"
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

void Accumulate(FillMetrics& sum, const FillMetrics& m, double w) {
  sum.mpjpe_unkeyed_cm += w * m.mpjpe_unkeyed_cm;
  sum.mpjpe_keyed_between_cm += w * m.mpjpe_keyed_between_cm;
  sum.angle_unkeyed_deg += w * m.angle_unkeyed_deg;
  sum.npss += w * m.npss;
  sum.jitter_ratio += w * m.jitter_ratio;
  sum.key_error_mean_deg += w * m.key_error_mean_deg;
  sum.key_error_max_deg = std::max(sum.key_error_max_deg, m.key_error_max_deg);  // worst, not mean
  sum.bone_length_error += w * m.bone_length_error;
  sum.unkeyed_joints = m.unkeyed_joints;
}

Result<MotionDatabase> BuildFoldDatabase(const std::vector<LabeledClip>& clips, const std::string& fold,
                                         const EvaluationOptions& options) {
  MotionDatabaseBuilder builder(options.database);
  for (const LabeledClip& c : clips)
    if (Label(c, options.fold_label) != fold) RETURN_IF_ERROR(builder.Add(c.skeleton, c.clip, c.labels));
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

// Scores the clips of `fold` (every clip when fold is empty) against `db`.
Status ScoreClips(const std::vector<LabeledClip>& clips, const std::string& fold, const MotionDatabase& db,
                  const EvaluationOptions& options, int total, EvaluationResult& result) {
  FillEngine engine(db);
  for (const LabeledClip& c : clips) {
    if (!fold.empty() && Label(c, options.fold_label) != fold) continue;
    const std::string content = Label(c, "content");
    if (!options.only_contents.empty() && !Contains(options.only_contents, content)) continue;
    ASSIGN_OR_RETURN(const MotionClip sketch, MakeSketch(c.skeleton, c.clip, options.sketch));
    for (const NamedMethod& method : options.methods) {
      const auto start = std::chrono::steady_clock::now();
      Result<FillResult> filled = engine.Fill(sketch, method.options);
      if (filled.ok() && options.plant_feet) {
        ASSIGN_OR_RETURN(const RigMapping mapping, MapHumanoid(db.skeleton(), {}));
        PlantFeet(db.skeleton(), LegsToPlant(mapping, sketch), options.feet, filled->clip);
      }
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (!filled.ok()) return filled.status().WithContext("clip '" + c.clip.name + "', method " + method.name);
      ASSIGN_OR_RETURN(FillMetrics metrics, ScoreFill(c.skeleton, c.clip, sketch, filled->clip, db.root_joint()));
      ClipScore score{c.clip.name, fold.empty() ? "against" : fold,
                      Contains(options.locomotion_contents, content) ? "locomotion" : "gestures",
                      method.name, metrics, seconds, seconds / std::max(1e-9, c.clip.duration_s())};
      CoverageFigures(filled->report.coverage, sketch.num_frames, score);
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

Status ScoreFold(const std::vector<LabeledClip>& clips, const std::string& fold, const EvaluationOptions& options,
                 int total, EvaluationResult& result) {
  ASSIGN_OR_RETURN(const MotionDatabase db, BuildFoldDatabase(clips, fold, options));
  return ScoreClips(clips, fold, db, options, total, result);
}

int CountTested(const std::vector<LabeledClip>& clips, const EvaluationOptions& options,
                const std::set<std::string>* folds) {
  int total = 0;
  for (const LabeledClip& c : clips)
    if ((!folds || folds->count(Label(c, options.fold_label))) &&
        (options.only_contents.empty() || Contains(options.only_contents, Label(c, "content"))))
      ++total;
  return total;
}

}  // namespace

Status EvaluationOptions::Validate() const {
  RETURN_IF_ERROR(sketch.Validate());
  if (fold_label.empty()) return InvalidArgument("fold_label: must name a clip label, e.g. style");
  if (methods.empty()) return InvalidArgument("methods: at least one method is needed");
  for (const NamedMethod& m : methods) RETURN_IF_ERROR(m.options.Validate().WithContext("method " + m.name));
  return database.Validate();
}

std::vector<SummaryRow> Summarise(const std::vector<ClipScore>& scores, const std::vector<NamedMethod>& methods) {
  std::vector<SummaryRow> rows;
  for (const NamedMethod& method : methods)
    for (const char* category : {"locomotion", "gestures", "all"}) {
      SummaryRow row;
      row.method = method.name;
      row.category = category;
      for (const ClipScore& s : scores)
        if (s.method == method.name && (row.category == "all" || s.category == row.category)) ++row.clips;
      if (row.clips == 0) continue;
      const double w = 1.0 / row.clips;
      for (const ClipScore& s : scores)
        if (s.method == method.name && (row.category == "all" || s.category == row.category)) {
          Accumulate(row.mean, s.metrics, w);
          row.coverage_median_unexplained += w * s.coverage_median_unexplained;
          row.poorly_covered_share += w * s.poorly_covered_share;
          row.fill_seconds += w * s.fill_seconds;
          row.seconds_per_s += w * s.seconds_per_s;
        }
      long contact_frames = 0;
      for (const ClipScore& s : scores)
        if (s.method == method.name && (row.category == "all" || s.category == row.category)) {
          contact_frames += s.metrics.foot_contact_frames;
          row.mean.foot_skate_cm_per_s += s.metrics.foot_skate_cm_per_s * s.metrics.foot_contact_frames;
          row.mean.foot_skate_share += s.metrics.foot_skate_share * s.metrics.foot_contact_frames;
        }
      row.mean.foot_contact_frames = contact_frames;
      if (contact_frames > 0) {
        row.mean.foot_skate_cm_per_s /= contact_frames;
        row.mean.foot_skate_share /= contact_frames;
      }
      rows.push_back(row);
    }
  return rows;
}

Result<EvaluationResult> RunLeaveOneOut(const std::vector<LabeledClip>& clips, const EvaluationOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  if (clips.size() < 2) return InvalidArgument("leave-one-out needs at least two clips");
  std::set<std::string> folds;
  for (const LabeledClip& c : clips) {
    const std::string fold = Label(c, options.fold_label);
    if (fold.empty()) return InvalidData("clip '" + c.clip.name + "' has no '" + options.fold_label + "' label");
    if (options.only_folds.empty() || Contains(options.only_folds, fold)) folds.insert(fold);
  }
  if (folds.empty()) return InvalidArgument("no clip belongs to the requested folds");
  const int total = CountTested(clips, options, &folds);
  EvaluationResult result;
  for (const std::string& fold : folds) {
    RETURN_IF_ERROR(ScoreFold(clips, fold, options, total, result).WithContext("fold '" + fold + "'"));
    ++result.folds;
  }
  result.summary = Summarise(result.scores, options.methods);
  return result;
}

Result<EvaluationResult> RunAgainstDatabase(const std::vector<LabeledClip>& tests,
                                            const std::vector<LabeledClip>& database, const EvaluationOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  if (tests.empty()) return InvalidArgument("no clip to test");
  if (database.empty()) return InvalidArgument("the database has no clip");
  MotionDatabaseBuilder builder(options.database);
  for (const LabeledClip& c : database) RETURN_IF_ERROR(builder.Add(c.skeleton, c.clip, c.labels));
  ASSIGN_OR_RETURN(const MotionDatabase db, builder.Build());
  EvaluationResult result;
  RETURN_IF_ERROR(ScoreClips(tests, "", db, options, CountTested(tests, options, nullptr), result));
  result.folds = 1;
  result.summary = Summarise(result.scores, options.methods);
  return result;
}

}  // namespace mocapfill
