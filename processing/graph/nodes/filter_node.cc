// filter: multiresolution band gains on every clip of a motion (processing/filtering/
// motion_filter.h; Bruderlin and Williams 1995), as the `filter` verb's --gains.
#include "processing/filtering/motion_filter.h"
#include "processing/graph/nodes/node_support.h"
#include "processing/graph/nodes/nodes.h"

namespace mocapfill::graph {

namespace {

class FilterNode : public Node {
 public:
  FilterNode(MultiresFilterOptions options, std::vector<std::string> joints)
      : options_(std::move(options)), joint_names_(std::move(joints)) {}

  Result<Value> Run(const NodeInputs& inputs, RunContext&) const override {
    const Scene& scene = inputs.Motion("motion");
    if (scene.clips.empty()) return InvalidData("motion: no animation to filter");
    MultiresFilterOptions options = options_;
    for (const std::string& name : joint_names_) {
      ASSIGN_OR_RETURN(const int joint, FindJointNamed(scene.skeleton, name, "motion (option joints)", ErrorCode::kInvalidData));
      options.joints.push_back(joint);
    }
    auto out = std::make_shared<Scene>(scene);
    for (MotionClip& clip : out->clips) {
      Result<MotionClip> filtered = MultiresFilter(scene.skeleton, clip, options);
      if (!filtered.ok()) return filtered.status().WithContext("clip '" + clip.name + "'");
      clip = std::move(filtered).value();
    }
    return Value(std::shared_ptr<const Scene>(std::move(out)));
  }

 private:
  MultiresFilterOptions options_;
  std::vector<std::string> joint_names_;
};

Result<std::unique_ptr<Node>> CreateFilter(const NodeOptions& o) {
  MultiresFilterOptions options;
  options.gains.band_gains = o.NumberList("gains");
  options.gains.residual_gain = o.Number("residual_gain");
  options.pyramid.levels = o.Int("levels");
  RETURN_IF_ERROR(options.Validate());
  return std::unique_ptr<Node>(new FilterNode(options, o.StringList("joints")));
}

}  // namespace

NodeTypeSpec FilterNodeSpec() {
  NodeTypeSpec spec;
  spec.type = "filter";
  spec.summary = "Scale frequency bands of every clip (multiresolution filtering)";
  spec.inputs = {{"motion", PortType::kMotion, false, "motion to filter"}};
  spec.output = PortSpec{"motion", PortType::kMotion, false, "the filtered motion (same frames and rate)"};
  OptionSpec gains = ListOption("gains", OptionType::kNumberList,
                                "gain per band, highest frequency first (missing gains are 1), e.g. [1, 1.5, 1.5]");
  gains.min = 0.0;
  gains.max = 10.0;
  spec.options = {
      gains,
      NumberOption("residual_gain", 1.0, 0.0, false, 10.0, "", "gain of the slowly varying average pose"),
      ListOption("joints", OptionType::kStringList, "joints to filter by name (empty = every joint)"),
      IntOption("levels", 0, 0, 16, "pyramid levels (0 = automatic from the clip length)"),
  };
  spec.create = CreateFilter;
  return spec;
}

}  // namespace mocapfill::graph
