#include "mocapfill/fill.h"

#include "library/api/access.h"
#include "library/fill_report_json.h"
#include "processing/sketch_fill/sketch_fill.h"

namespace mocapfill::api {

namespace {

Result<SketchFillOptions> ToSketchFillOptions(const FillOptions& options) {
  SketchFillOptions out;
  ASSIGN_OR_RETURN(out.fill.method, ParseFillMethod(options.method));
  ASSIGN_OR_RETURN(out.rest, ParseRestSource(options.rest));
  if (options.coverage != "blend" && options.coverage != "warn")
    return InvalidArgument("coverage: expected blend or warn, got '" + options.coverage + "'");
  if (options.output_rate_hz < 0.0) return InvalidArgument("output_rate_hz: must be 0 (the sketch's) or positive");
  if (options.threads < 0) return InvalidArgument("threads: must be 0 (every core) or positive");
  out.fill.texture = options.texture;
  out.fill.coverage.blend = options.coverage == "blend";
  out.fill.threads = options.threads;
  RETURN_IF_ERROR(out.fill.Validate());
  out.map = options.map;
  out.output_rate_hz = options.output_rate_hz;
  out.keep = options.keep;
  out.synthesize = options.synthesize;
  out.position_keys = options.position_keys;
  out.plant_feet = options.plant_feet;
  return out;
}

}  // namespace

FillResult Fill(const Scene& sketch, const Database& database, const FillOptions& options) {
  const SketchFillOptions fill_options = ValueOrThrow(ToSketchFillOptions(options), FailureStage::kProcessing);
  mocapfill::Scene scene = SceneAccess::Get(sketch);
  if (scene.clips.size() > 1) scene.clips.resize(1);  // the first animation is the sketch
  const mocapfill::PcaModel* model = options.pca_model ? &PcaModelAccess::Get(*options.pca_model) : nullptr;
  Result<SketchFillResult> filled = FillSketch(scene, DatabaseAccess::Get(database), fill_options, model);
  if (!filled.ok()) {
    // As the CLI classes it: a sketch or map the fill cannot read is bad input.
    const bool input = filled.status().code() == ErrorCode::kInvalidData;
    ThrowIfError(filled.status(), input ? FailureStage::kInput : FailureStage::kProcessing);
  }
  FillResult result;
  result.report_json = FillReportJson(*filled, DatabaseAccess::Name(database), 0.0);
  result.key_error_mean_deg = filled->key_error_mean_deg;
  result.key_error_max_deg = filled->key_error_max_deg;
  result.warnings = filled->warnings;
  result.scene = SceneAccess::Wrap(std::move(filled->scene));
  return result;
}

}  // namespace mocapfill::api
