// filter: multiresolution band gains on every clip of a motion (processing/filtering/
// motion_filter.h; Bruderlin and Williams 1995), as the `filter` verb's --gains.
#include "processing/core/motion_database.h"
#include "processing/filtering/motion_filter.h"
#include "processing/filtering/pyramid.h"
#include "processing/graph/nodes/node_support.h"
#include "processing/graph/nodes/nodes.h"

namespace mocapfill::graph {

namespace {

// The database's joint means re-indexed for the motion's skeleton, so that filtering happens
// about the database's reference. kInvalidData naming a joint the database lacks.
Result<TangentReference> ReferenceFor(const Skeleton& skeleton, const MotionDatabase& db) {
  TangentReference reference;
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const std::optional<int> d = db.skeleton().Find(skeleton.name(j));
    if (!d) return InvalidData("motion: joint '" + skeleton.name(j) + "' is not in the database's skeleton");
    reference.joint_means.push_back(db.joint_means()[*d]);
    if (*d == db.root_joint()) reference.root_joint = j;
  }
  return reference;
}

// "gains for L7..L11 are ignored: ..." when more gains are given than the clip has bands (the
// gains beyond are 1, since any other value is an error of MultiresFilter).
std::optional<std::string> UnusedGains(const MotionClip& clip, const MultiresFilterOptions& options) {
  const int levels = options.pyramid.levels > 0 ? options.pyramid.levels
                                                : AutomaticLevels(clip.num_frames, clip.sample_rate_hz);
  const int given = static_cast<int>(options.gains.band_gains.size());
  if (given <= levels) return std::nullopt;
  return "clip '" + clip.name + "': gains for L" + std::to_string(levels) + ".." + "L" + std::to_string(given - 1) +
         " are ignored: its " + std::to_string(clip.num_frames) + " frames give " + std::to_string(levels) +
         " band-pass levels (L0..L" + std::to_string(levels - 1) + ")";
}

class FilterNode : public Node {
 public:
  FilterNode(MultiresFilterOptions options, std::vector<std::string> joints)
      : options_(std::move(options)), joint_names_(std::move(joints)) {}

  Result<Value> Run(const NodeInputs& inputs, RunContext& context) const override {
    const Scene& scene = inputs.Motion("motion");
    if (scene.clips.empty()) return InvalidData("motion: no animation to filter");
    MultiresFilterOptions options = options_;
    for (const std::string& name : joint_names_) {
      ASSIGN_OR_RETURN(const int joint, FindJointNamed(scene.skeleton, name, "joints"));
      options.joints.push_back(joint);
    }
    TangentReference reference;
    if (inputs.Has("database")) {
      ASSIGN_OR_RETURN(reference, ReferenceFor(scene.skeleton, inputs.Database("database")));
      options.reference = &reference;
    }
    auto out = std::make_shared<Scene>(scene);
    for (MotionClip& clip : out->clips) {
      if (const std::optional<std::string> unused = UnusedGains(clip, options)) context.warnings.push_back(*unused);
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
  options.pyramid.boundary = o.Bool("periodic") ? PyramidBoundary::kPeriodic : PyramidBoundary::kClamp;
  RETURN_IF_ERROR(options.Validate());
  return std::unique_ptr<Node>(new FilterNode(options, o.StringList("joints")));
}

}  // namespace

NodeTypeSpec FilterNodeSpec() {
  NodeTypeSpec spec;
  spec.type = "filter";
  spec.summary = "Scale frequency bands of every clip (multiresolution filtering)";
  spec.inputs = {{"motion", PortType::kMotion, false, "motion to filter"},
                 {"database", PortType::kDatabase, true, "filter about this database's joint means (optional)"}};
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
      BoolOption("periodic", false, "treat the clip as cyclic (wrap around instead of holding the ends)"),
  };
  spec.create = CreateFilter;
  return spec;
}

}  // namespace mocapfill::graph
