#include "mocapfill/fill.h"

#include <algorithm>

#include "library/api/access.h"
#include "library/fill_report_json.h"
#include "processing/graph/nodes/fill_schema.h"
#include "processing/graph/nodes/nodes.h"
#include "processing/sketch_fill/sketch_fill.h"

namespace mocapfill::api {

namespace {

graph::OptionValue Strings(const std::vector<std::string>& items) {
  std::vector<graph::OptionValue> values;
  for (const std::string& item : items) values.push_back(graph::OptionValue::String(item));
  return graph::OptionValue::Array(std::move(values));
}

// The options through the fill's schema (graph/nodes/fill_schema.h), as the command line and
// pipelines take them: the same defaults, ranges and messages ('option "threads": ...').
Result<SketchFillOptions> ToSketchFillOptions(const FillOptions& options) {
  if (options.coverage != "blend" && options.coverage != "warn")
    return InvalidArgument("option \"coverage\": expected blend or warn, got '" + options.coverage + "'");
  std::vector<std::string> map_keys;
  std::vector<graph::OptionValue> map_values;
  for (const auto& [joint, bone] : options.map) {
    map_keys.push_back(joint);
    map_values.push_back(graph::OptionValue::String(bone));
  }
  std::vector<std::pair<std::string, graph::OptionValue>> given = {
      {"method", graph::OptionValue::String(options.method)},
      {"rename", graph::OptionValue::Object(std::move(map_keys), std::move(map_values))},
      {"rest", graph::OptionValue::String(options.rest)},
      {"rate_hz", graph::OptionValue::Number(options.output_rate_hz, false)},
      {"keep", Strings(options.keep)},
      {"synthesize", Strings(options.synthesize)},
      {"position_keys", Strings(options.position_keys)},
      {"plant_feet", graph::OptionValue::Bool(options.plant_feet)},
      {"texture", graph::OptionValue::Bool(options.texture)},
      {"blend_poor_coverage", graph::OptionValue::Bool(options.coverage == "blend")},
      {"threads", graph::OptionValue::Integer(options.threads)},
  };
  const graph::NodeTypeSpec spec = graph::FillNodeSpec();
  for (const auto& entry : options.more) {
    const std::string& name = entry.first;  // a named reference: clang 14 captures no structured binding
    const std::string& text = entry.second;
    const auto option = std::find_if(spec.options.begin(), spec.options.end(),
                                     [&](const graph::OptionSpec& o) { return o.name == name; });
    // An unknown name goes through as text for CheckNodeOptions to list the valid ones.
    if (option == spec.options.end()) {
      given.emplace_back(name, graph::OptionValue::String(text));
      continue;
    }
    ASSIGN_OR_RETURN(graph::OptionValue value, graph::OptionValueFromText(*option, text, "option \"" + name + "\""));
    given.emplace_back(name, std::move(value));
  }
  ASSIGN_OR_RETURN(const graph::NodeOptions checked, graph::CheckNodeOptions(spec, given));
  return graph::SketchFillOptionsFrom(checked);
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
