// fill: completes the sketch's missing joints from a database, as the `fill` verb does: one
// call of the fill use case (processing/sketch_fill), which maps the sketch's rig to the
// canonical humanoid, fills on the database's rig and returns the sketch's rig at its rate.
#include <algorithm>

#include "processing/graph/nodes/fill_schema.h"
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

Result<std::unique_ptr<Node>> CreateFill(const NodeOptions& o) {
  ASSIGN_OR_RETURN(SketchFillOptions options, SketchFillOptionsFrom(o));
  return std::unique_ptr<Node>(new FillNode(std::move(options)));
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
  spec.options = SketchFillOptionSpecs();
  spec.create = CreateFill;
  return spec;
}

}  // namespace mocapfill::graph
