// fill: completes the sketch's missing joints from a database, as the `fill` verb does: one
// call of the fill use case (processing/sketch_fill), which maps the sketch's rig to the
// canonical humanoid, fills on the database's rig and returns the sketch's rig at its rate.
#include <algorithm>

#include "processing/graph/nodes/node_support.h"
#include "processing/graph/nodes/nodes.h"
#include "processing/sketch_fill/sketch_fill.h"

namespace mocapfill::graph {

namespace {

class FillNode : public Node {
 public:
  explicit FillNode(SketchFillOptions options) : options_(std::move(options)) {}

  Result<Value> Run(const NodeInputs& inputs, RunContext& context) const override {
    const Scene& scene = inputs.Motion("sketch");
    const MotionDatabase& db = inputs.Database("database");
    ASSIGN_OR_RETURN(const MotionClip* first, FirstClip(scene, "sketch"));
    Scene sketch = scene;
    sketch.clips = {*first};
    // The pca and hybrid methods use a given model, else build one from the database.
    const PcaModel* model = inputs.Has("model") ? &inputs.Model("model") : nullptr;
    Result<SketchFillResult> filled = FillSketch(sketch, db, options_, model);
    if (!filled.ok()) return filled.status().WithContext("sketch");
    for (const std::string& w : filled->warnings) context.warnings.push_back("sketch: " + w);
    MotionClip clip = filled->scene.clips.front();
    context.fill = std::make_shared<const SketchFillResult>(std::move(filled).value());
    return WithClip(scene, std::move(clip));
  }

 private:
  SketchFillOptions options_;
};

OptionSpec MethodOption() {
  OptionSpec spec = StringOption("method", "hierarchical", {},
                                 "fill method; every name ParseFillMethod knows (mean, nn, fragment, hierarchical, ...)");
  spec.check = [](const OptionValue& v) { return ParseFillMethod(v.text).status(); };
  return spec;
}

OptionSpec RestOption() {
  OptionSpec spec = StringOption("rest", "auto", RestSourceNames(), "the sketch rig's rest pose");
  spec.check = [](const OptionValue& v) { return ParseRestSource(v.text).status(); };
  return spec;
}

OptionSpec JoinOption() {
  OptionSpec spec = StringOption("join", "cost-matrix", {}, "fragment join criterion: cost-matrix, best-fragment or best-animation");
  spec.check = [](const OptionValue& v) { return ParseJoinCriterion(v.text).status(); };
  return spec;
}

Result<std::unique_ptr<Node>> CreateFill(const NodeOptions& o) {
  SketchFillOptions sketch_options;
  FillOptions& options = sketch_options.fill;
  options.method = *ParseFillMethod(o.String("method"));
  options.join = *ParseJoinCriterion(o.String("join"));
  options.texture = o.Bool("texture");
  options.repin_keys = o.Bool("repin_keys");
  options.candidates = o.Int("candidates");
  options.blend = o.Int("blend");
  options.max_drivers = o.Int("max_drivers");
  options.fragment_band_hz = o.Number("fragment_band_hz");
  options.threads = o.Int("threads");
  options.coverage.blend = o.Bool("blend_poor_coverage");
  RETURN_IF_ERROR(options.Validate());
  ASSIGN_OR_RETURN(sketch_options.rest, ParseRestSource(o.String("rest")));
  sketch_options.output_rate_hz = o.Number("rate_hz");
  sketch_options.map = o.StringMap("rename");
  sketch_options.keep = o.StringList("keep");
  sketch_options.synthesize = o.StringList("synthesize");
  sketch_options.position_keys = o.StringList("position_keys");
  sketch_options.plant_feet = o.Bool("plant_feet");
  return std::unique_ptr<Node>(new FillNode(std::move(sketch_options)));
}

}  // namespace

NodeTypeSpec FillNodeSpec() {
  NodeTypeSpec spec;
  spec.type = "fill";
  spec.summary = "Fill the sketch's unkeyed joints from a motion database (as `mocapfill fill`)";
  spec.inputs = {{"sketch", PortType::kMotion, false, "keyframed sketch; joints with keys are kept"},
                 {"database", PortType::kDatabase, false, "motion database the missing joints come from"},
                 {"model", PortType::kPcaModel, true,
                  "PCA model of the pca and hybrid methods (default: built from the database)"}};
  spec.output = PortSpec{"motion", PortType::kMotion, false, "the sketch's asset with a complete animation at the sketch's rate"};
  spec.options = {
      MethodOption(),
      JoinOption(),
      BoolOption("texture", true, "add the matched fragments' high bands to keyed joints"),
      BoolOption("repin_keys", true, "restore the exact keys after texturing"),
      IntOption("candidates", 128, 1, std::nullopt, "best candidates kept per fragment"),
      IntOption("blend", 128, 1, std::nullopt, "candidates averaged per fragment (1 = the joined one alone)"),
      IntOption("max_drivers", 3, 0, std::nullopt, "hierarchical: driving joints per group (0 = all)"),
      NumberOption("fragment_band_hz", 1.0, 0.0, true, std::nullopt, "Hz", "peak frequency of the fragmentation band"),
      IntOption("threads", 0, 0, std::nullopt, "matching threads (0 = all cores)"),
      BoolOption("blend_poor_coverage", true,
                 "blend stretches the database covers poorly towards its mean pose (false: only warn)"),
      ListOption("rename", OptionType::kStringMap,
                 "rig map overrides: sketch joint -> canonical bone or database joint, e.g. {\"Hip\": \"hips\"}"),
      RestOption(),
      NumberOption("rate_hz", 0.0, 0.0, false, 1000.0, "Hz", "output rate (0 = the sketch's own)"),
      ListOption("keep", OptionType::kStringList, "only these joints stay keyed; every other joint is synthesised"),
      ListOption("synthesize", OptionType::kStringList, "joints synthesised even when keyed"),
      ListOption("position_keys", OptionType::kStringList,
                 "joints whose translation keys are world-space position targets (hybrid method)"),
      BoolOption("plant_feet", true, "hold a foot standing at two consecutive keys between them (leg IK)"),
  };
  spec.create = CreateFill;
  return spec;
}

}  // namespace mocapfill::graph
