// PCA nodes (thesis chapters 5 and 6): pca_build (a model of a database, in memory), pca_fit (the
// sketch's keys fitted by the model: closed form, or the Ceres fit optionally guided by a fill
// result) and pca_edit (component dials in standard deviations, as `mocapfill pca edit`).
#include <cmath>

#include "processing/graph/nodes/node_support.h"
#include "processing/graph/nodes/nodes.h"
#include "processing/pca/pca_clip.h"
#include "processing/pca/pca_edit.h"
#include "processing/pca/pca_model_builder.h"
#include "processing/pca/pca_sketch.h"

namespace mocapfill::graph {

namespace {

class PcaBuildNode : public Node {
 public:
  explicit PcaBuildNode(PcaModelOptions options) : options_(std::move(options)) {}
  Result<Value> Run(const NodeInputs& inputs, RunContext&) const override {
    ASSIGN_OR_RETURN(PcaModel model, BuildPcaModel(inputs.Database("database"), options_));
    return Value(std::shared_ptr<const PcaModel>(std::make_shared<PcaModel>(std::move(model))));
  }

 private:
  PcaModelOptions options_;
};

Result<std::unique_ptr<Node>> CreatePcaBuild(const NodeOptions& o) {
  PcaModelOptions options;
  options.basis.variance_kept = o.Number("variance");
  options.basis.max_components = o.Int("max_components");
  options.basis.window_frames = o.Int("window_frames");
  options.basis.window_stride_frames = o.Int("window_stride_frames");
  options.labels = o.StringList("labels");
  RETURN_IF_ERROR(options.Validate());
  return std::unique_ptr<Node>(new PcaBuildNode(options));
}

class PcaFitNode : public Node {
 public:
  PcaFitNode(bool closed_form, PcaSketchFitOptions options) : closed_form_(closed_form), options_(options) {}

  Result<Value> Run(const NodeInputs& inputs, RunContext&) const override {
    const Scene& scene = inputs.Motion("sketch");
    const PcaModel& model = inputs.Model("model");
    ASSIGN_OR_RETURN(const MotionClip* first, FirstClip(scene, "sketch"));
    ASSIGN_OR_RETURN(const MotionClip sketch, AtRate(*first, model.sample_rate_hz));
    if (closed_form_) {
      PcaFillOptions fill;
      fill.closed_form.noise_deg = options_.fit.key_sigma_deg;
      ASSIGN_OR_RETURN(MotionClip filled, FillMissingJointsPca(model, scene.skeleton, sketch, fill));
      return WithClip(scene, std::move(filled));
    }
    std::optional<MotionClip> guide;
    if (inputs.Has("guide")) {
      const Scene& guide_scene = inputs.Motion("guide");
      RETURN_IF_ERROR(CheckSameJoints(scene.skeleton, guide_scene.skeleton, "sketch", "guide"));
      ASSIGN_OR_RETURN(const MotionClip* guide_clip, FirstClip(guide_scene, "guide"));
      ASSIGN_OR_RETURN(guide, AtRate(*guide_clip, model.sample_rate_hz));
      if (guide->num_frames != sketch.num_frames)
        return InvalidData("guide: " + std::to_string(guide->num_frames) + " frames, the sketch has " +
                           std::to_string(sketch.num_frames) + " at " + std::to_string(model.sample_rate_hz) + " Hz");
    }
    ASSIGN_OR_RETURN(PcaSketchFit fit,
                     FitSketchToKeys(model, scene.skeleton, sketch, {}, guide ? &*guide : nullptr, options_));
    return WithClip(scene, std::move(fit.clip));
  }

 private:
  bool closed_form_;
  PcaSketchFitOptions options_;
};

Result<std::unique_ptr<Node>> CreatePcaFit(const NodeOptions& o) {
  PcaSketchFitOptions options;
  const std::string& variant = o.String("variant");
  options.full_pose = variant == "full_pose";
  options.fit.key_sigma_deg = o.Number("key_sigma_deg");
  options.fit.guide_sigma_deg = o.Number("guide_sigma_deg");
  options.fit.max_iterations = o.Int("max_iterations");
  options.fit.num_threads = o.Int("threads");
  RETURN_IF_ERROR(options.Validate());
  return std::unique_ptr<Node>(new PcaFitNode(variant == "closed_form", options));
}

// Each dial moves one component on every frame; a window model works at its own rate.
Result<MotionClip> EditClip(const PcaModel& model, const Skeleton& skeleton, const MotionClip& input,
                            const PcaEditOptions& options) {
  MotionClip clip = input;
  if (model.window_frames > 1) {
    ASSIGN_OR_RETURN(clip, AtRate(input, model.sample_rate_hz));
  }
  ASSIGN_OR_RETURN(const PcaBinding binding, BindPcaModel(model, skeleton));
  const EncodedClip encoded = EncodeClip(model, binding, skeleton, clip);
  ASSIGN_OR_RETURN(const Eigen::MatrixXd edited, EditPoses(model, encoded.poses, options));
  return DecodeClip(model, binding, skeleton, encoded, edited, clip);
}

class PcaEditNode : public Node {
 public:
  explicit PcaEditNode(PcaEditOptions options) : options_(std::move(options)) {}

  Result<Value> Run(const NodeInputs& inputs, RunContext&) const override {
    const Scene& scene = inputs.Motion("motion");
    const PcaModel& model = inputs.Model("model");
    // Component numbers beyond the model are the pipeline's mistake, hence the option name.
    RETURN_IF_ERROR(options_.Validate(model).WithContext("option \"components\""));
    if (scene.clips.empty()) return InvalidData("motion: no animation to edit");
    auto out = std::make_shared<Scene>(scene);
    for (MotionClip& clip : out->clips) {
      Result<MotionClip> edited = EditClip(model, scene.skeleton, clip, options_);
      if (!edited.ok()) return edited.status().WithContext("clip '" + clip.name + "'");
      clip = std::move(edited).value();
    }
    return Value(std::shared_ptr<const Scene>(std::move(out)));
  }

 private:
  PcaEditOptions options_;
};

Result<std::unique_ptr<Node>> CreatePcaEdit(const NodeOptions& o) {
  PcaEditOptions options;
  options.keep_residual = o.Bool("keep_residual");
  options.max_abs_sigmas = o.Number("max_abs_sigmas");
  for (const auto& [key, sigmas] : o.NumberMap("components")) {
    size_t used = 0;
    int component = 0;
    try {
      component = std::stoi(key, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != key.size() || component < 1)
      return InvalidArgument("option \"components\": key \"" + key + "\": expected a component number >= 1");
    if (std::abs(sigmas) > options.max_abs_sigmas)
      return InvalidArgument("option \"components\": \"" + key + "\": |sigmas| must be <= max_abs_sigmas (" +
                             std::to_string(options.max_abs_sigmas) + "), got " + std::to_string(sigmas));
    options.dials.push_back({component - 1, sigmas});
  }
  return std::unique_ptr<Node>(new PcaEditNode(options));
}

}  // namespace

NodeTypeSpec PcaBuildNodeSpec() {
  NodeTypeSpec spec;
  spec.type = "pca_build";
  spec.summary = "Build a PCA model of (some behaviours of) a database, in memory";
  spec.inputs = {{"database", PortType::kDatabase, false, "database the model is estimated from"}};
  spec.output = PortSpec{"model", PortType::kPcaModel, false, "the PCA model"};
  spec.options = {
      NumberOption("variance", 0.95, 0.0, true, 1.0, "", "share of the variance kept"),
      IntOption("max_components", 30, 1, std::nullopt, "upper bound on components"),
      WithFlag(IntOption("window_frames", 1, 1, std::nullopt, "1 = pose PCA; W > 1 = window PCA over W frames", "frames"),
               "window"),
      WithFlag(IntOption("window_stride_frames", 1, 1, std::nullopt, "hop between estimation windows", "frames"),
               "window-stride"),
      ListOption("labels", OptionType::kStringList, "only clips with one of these labels (\"walk\", \"style=happy\")"),
  };
  spec.create = CreatePcaBuild;
  return spec;
}

NodeTypeSpec PcaFitNodeSpec() {
  NodeTypeSpec spec;
  spec.type = "pca_fit";
  spec.summary = "Fit a PCA model to the sketch's keys (missing joints from the model's prior)";
  spec.inputs = {{"sketch", PortType::kMotion, false, "keyframed sketch (joints named as in the model)"},
                 {"model", PortType::kPcaModel, false, "pose PCA model"},
                 {"guide", PortType::kMotion, true, "optional motion the unkeyed joints are pulled towards (a fill result)"}};
  spec.output = PortSpec{"motion", PortType::kMotion, false, "the fitted motion at the model's rate, keys kept"};
  spec.options = {
      StringOption("variant", "subspace", {"subspace", "full_pose", "closed_form"},
                   "subspace: keys within key_sigma_deg; full_pose: keys hold exactly; closed_form: per-frame conditional mean"),
      NumberOption("key_sigma_deg", 1.0, 0.0, true, std::nullopt, "deg", "tolerance of rotation keys (closed_form: observation noise)"),
      NumberOption("guide_sigma_deg", 10.0, 0.0, true, std::nullopt, "deg", "tolerance of the guide"),
      IntOption("max_iterations", 50, 1, std::nullopt, "Levenberg-Marquardt iterations"),
      IntOption("threads", 0, 0, std::nullopt, "solver threads (0 = all cores)"),
  };
  spec.create = CreatePcaFit;
  return spec;
}

NodeTypeSpec PcaEditNodeSpec() {
  NodeTypeSpec spec;
  spec.type = "pca_edit";
  spec.summary = "Move a motion along principal components, in standard deviations";
  spec.inputs = {{"motion", PortType::kMotion, false, "motion to edit"},
                 {"model", PortType::kPcaModel, false, "PCA model"}};
  spec.output = PortSpec{"motion", PortType::kMotion, false, "the edited motion"};
  OptionSpec components = WithFlag(ListOption("components", OptionType::kNumberMap,
                                              "1-based component -> change in standard deviations, e.g. {\"1\": 2.0}"),
                                   "component");
  components.unit = "sigmas";
  spec.options = {
      components,
      BoolOption("keep_residual", true, "keep the detail the model does not explain"),
      NumberOption("max_abs_sigmas", 3.0, 0.0, true, std::nullopt, "sigmas", "bound on |sigmas| of a dial"),
  };
  spec.create = CreatePcaEdit;
  return spec;
}

}  // namespace mocapfill::graph
