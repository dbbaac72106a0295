#include "processing/fill/fill_engine.h"

#include <utility>

#include "processing/hybrid/hybrid_fill.h"
#include "processing/synthesis/fill_stages.h"
#include "processing/synthesis/sketch_signals.h"

namespace mocapfill {

namespace {

bool SameModelOptions(const PcaModelOptions& a, const PcaModelOptions& b) {
  return a.basis.variance_kept == b.basis.variance_kept && a.basis.max_components == b.basis.max_components &&
         a.basis.window_frames == b.basis.window_frames &&
         a.basis.window_stride_frames == b.basis.window_stride_frames && a.labels == b.labels &&
         a.root_rate_horizon_s == b.root_rate_horizon_s;
}

}  // namespace

FillEngine::FillEngine(const MotionDatabase& db) : db_(db), fragments_(db) {}
FillEngine::~FillEngine() = default;

Result<FillResult> FillEngine::Fill(const MotionClip& sketch, const FillOptions& options) {
  return Fill(sketch, options, {});
}

Result<FillResult> FillEngine::Fill(const MotionClip& sketch, const FillOptions& options,
                                    const std::vector<SketchPositionKey>& position_keys) {
  RETURN_IF_ERROR(options.Validate());
  RETURN_IF_ERROR(CheckFillSketch(db_, sketch));
  if (options.method == FillMethod::kPca) return FillPca(sketch, options);
  if (options.method == FillMethod::kHybrid) return FillHybrid(sketch, options, position_keys);
  if (!position_keys.empty()) return InvalidArgument("position keys need the hybrid method");
  FillResult result;
  ASSIGN_OR_RETURN(result.clip, fragments_.Fill(sketch, options, result.report));
  return result;
}

Result<const PcaModel*> FillEngine::Model(const FillOptions& options, FillReport& report) {
  if (given_model_ != nullptr) {
    report.pca_model_source = "given";
  } else {
    if (!built_model_ || !SameModelOptions(built_model_options_, options.pca.model)) {
      ASSIGN_OR_RETURN(PcaModel model, BuildPcaModel(db_, options.pca.model));
      built_model_ = std::make_unique<PcaModel>(std::move(model));
      built_model_options_ = options.pca.model;
    }
    report.pca_model_source = "built from the database";
  }
  const PcaModel* model = given_model_ != nullptr ? given_model_ : built_model_.get();
  report.pca_components = model->num_components();
  return model;
}

// The `pca` method is the PCA model's closed-form fit per frame (processing/pca,
// FillMissingJointsPca); the engine adds the report.
Result<FillResult> FillEngine::FillPca(const MotionClip& sketch, const FillOptions& options) {
  FillResult result;
  FillReport& report = result.report;
  report.method = FillMethodName(FillMethod::kPca);
  report.join = "none";
  report.frames = sketch.num_frames;
  report.rate_hz = db_.rate_hz();
  StageTimer timer(report);
  ASSIGN_OR_RETURN(const PcaModel* model, Model(options, report));
  timer.Mark("pca_model");
  ASSIGN_OR_RETURN(const SketchSignals s, MakeSketchSignals(db_, sketch));
  report.key_spacing_frames = s.key_spacing;
  timer.Mark("prepare");
  PcaFillOptions fill;
  fill.closed_form = options.pca.closed_form;
  ASSIGN_OR_RETURN(result.clip, FillMissingJointsPca(*model, db_.skeleton(), sketch, fill));
  result.clip.MakeContinuous();
  result.clip.KeyAllFrames();
  timer.Mark("closed_form");
  ReportJoints(db_, s, sketch, result.clip, false, report);
  timer.Mark("report");
  return result;
}

Result<FillResult> FillEngine::FillHybrid(const MotionClip& sketch, const FillOptions& options,
                                          const std::vector<SketchPositionKey>& position_keys) {
  FillResult result;
  FillReport& report = result.report;
  StageTimer timer(report);
  ASSIGN_OR_RETURN(const PcaModel* model, Model(options, report));
  timer.Mark("pca_model");
  ASSIGN_OR_RETURN(HybridResult hybrid,
                   HybridFill(fragments_, *model, sketch, options, options.pca, position_keys, report));
  result.clip = std::move(hybrid.clip);
  report.has_solver = true;
  report.solver = std::move(hybrid.solver);
  return result;
}

}  // namespace mocapfill
