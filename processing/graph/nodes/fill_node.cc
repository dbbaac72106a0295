// fill: completes the sketch's missing joints from a database (processing/synthesis/fill.h),
// as the `fill` verb does: the sketch is mapped onto the database skeleton by joint name,
// resampled to the database rate, filled, and put back on the sketch's skeleton.
#include <algorithm>

#include "processing/graph/nodes/node_support.h"
#include "processing/graph/nodes/nodes.h"
#include "processing/synthesis/fill.h"
#include "processing/synthesis/skeleton_map.h"

namespace mocapfill::graph {

namespace {

class FillNode : public Node {
 public:
  FillNode(FillOptions options, std::map<std::string, std::string> rename, std::vector<std::string> keep,
           std::vector<std::string> synthesize)
      : options_(std::move(options)), rename_(std::move(rename)), keep_(std::move(keep)),
        synthesize_(std::move(synthesize)) {}

  Result<Value> Run(const NodeInputs& inputs, RunContext& context) const override {
    const Scene& scene = inputs.Motion("sketch");
    const MotionDatabase& db = inputs.Database("database");
    ASSIGN_OR_RETURN(const MotionClip* first, FirstClip(scene, "sketch"));
    MotionClip clip = *first;
    RETURN_IF_ERROR(ApplyKeyOverrides(scene.skeleton, clip));
    if (std::all_of(clip.keys.begin(), clip.keys.end(), [](const JointKeys& k) { return k.empty(); }))
      return InvalidData("sketch: no keyed joint (nothing to fill from)");
    ASSIGN_OR_RETURN(const SkeletonMapping mapping, MapSkeletons(scene.skeleton, clip, db.skeleton(), rename_));
    for (const std::string& w : mapping.warnings) context.warnings.push_back("sketch: " + w);
    ASSIGN_OR_RETURN(const MotionClip sketch, AtRate(clip, db.rate_hz()));
    FillEngine engine(db);
    // The pca and hybrid methods use a given model, else build one from the database.
    if (inputs.Has("model")) engine.SetPcaModel(&inputs.Model("model"));
    ASSIGN_OR_RETURN(FillResult filled, engine.Fill(ToDatabaseClip(mapping, db.skeleton(), sketch), options_));
    return WithClip(scene, ToSketchClip(mapping, filled.clip, sketch, db.root_joint()));
  }

 private:
  // "synthesize" drops the keys of the listed joints; "keep" drops the keys of all others.
  Status ApplyKeyOverrides(const Skeleton& skeleton, MotionClip& clip) const {
    for (const auto* list : {&synthesize_, &keep_})
      for (const std::string& name : *list)
        if (!skeleton.Find(name)) return InvalidData("sketch: joint '" + name + "' (option keep/synthesize) is not in the sketch");
    for (int j = 0; j < skeleton.num_joints(); ++j) {
      const std::string& name = skeleton.name(j);
      const bool synth = std::find(synthesize_.begin(), synthesize_.end(), name) != synthesize_.end();
      const bool kept = std::find(keep_.begin(), keep_.end(), name) != keep_.end();
      if (synth || (!keep_.empty() && !kept)) clip.keys[j] = JointKeys{};
    }
    return OkStatus();
  }

  FillOptions options_;
  std::map<std::string, std::string> rename_;
  std::vector<std::string> keep_, synthesize_;
};

OptionSpec MethodOption() {
  OptionSpec spec = StringOption("method", "hierarchical", {},
                                 "fill method; every name ParseFillMethod knows (mean, nn, fragment, hierarchical, ...)");
  spec.check = [](const OptionValue& v) { return ParseFillMethod(v.text).status(); };
  return spec;
}

OptionSpec JoinOption() {
  OptionSpec spec = StringOption("join", "cost-matrix", {}, "fragment join criterion: cost-matrix, best-fragment or best-animation");
  spec.check = [](const OptionValue& v) { return ParseJoinCriterion(v.text).status(); };
  return spec;
}

Result<std::unique_ptr<Node>> CreateFill(const NodeOptions& o) {
  FillOptions options;
  options.method = *ParseFillMethod(o.String("method"));
  options.join = *ParseJoinCriterion(o.String("join"));
  options.texture = o.Bool("texture");
  options.repin_keys = o.Bool("repin_keys");
  options.candidates = o.Int("candidates");
  options.blend = o.Int("blend");
  options.max_drivers = o.Int("max_drivers");
  options.fragment_band_hz = o.Number("fragment_band_hz");
  options.threads = o.Int("threads");
  RETURN_IF_ERROR(options.Validate());
  return std::unique_ptr<Node>(
      new FillNode(options, o.StringMap("rename"), o.StringList("keep"), o.StringList("synthesize")));
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
  spec.output = PortSpec{"motion", PortType::kMotion, false, "the sketch's asset with a complete animation at the database rate"};
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
      ListOption("rename", OptionType::kStringMap, "sketch joint -> database joint names, e.g. {\"Hip\": \"Hips\"}"),
      ListOption("keep", OptionType::kStringList, "only these joints stay keyed; every other joint is synthesised"),
      ListOption("synthesize", OptionType::kStringList, "joints synthesised even when keyed"),
  };
  spec.create = CreateFill;
  return spec;
}

}  // namespace mocapfill::graph
