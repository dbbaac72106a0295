#include "processing/graph/nodes/fill_schema.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "processing/graph/nodes/node_support.h"

namespace mocapfill::graph {

namespace {

std::string FillOptionLabel(const std::function<std::string(const std::string&)>& label, const std::string& name) {
  return label ? label(name) : "option \"" + name + "\"";
}

// "1": component 1 on the command line and in files, 0 in ComponentDial.
Result<std::vector<ComponentDial>> DialsOf(const std::map<std::string, double>& given, const std::string& label) {
  std::vector<ComponentDial> dials;
  for (const auto& [key, sigmas] : given) {
    const bool digits = !key.empty() && key.size() < 7 && std::all_of(key.begin(), key.end(), ::isdigit);
    const int component = digits ? std::stoi(key) : 0;
    if (component < 1) {
      char value[32];
      std::snprintf(value, sizeof value, "%g", sigmas);
      return InvalidArgument(label + " '" + key + "=" + value +
                             "': expected <component>=<sigmas> with a component number >= 1, e.g. 1=+2.0");
    }
    dials.push_back({component - 1, sigmas});
  }
  return dials;
}

}  // namespace

std::vector<OptionSpec> FillMethodOptionSpecs() {
  const FillOptions d;
  const PcaMethodOptions& pca = d.pca;
  return {
      WithCheck(StringOption("method", "hierarchical", {}, "fill method: hierarchical, fragment, nn, mean, pca or hybrid"),
              [](const OptionValue& v) { return ParseFillMethod(v.text).status(); }),
      WithCheck(StringOption("join", "cost-matrix", {}, "fragment join criterion: cost-matrix, best-fragment or best-animation"),
              [](const OptionValue& v) { return ParseJoinCriterion(v.text).status(); }),
      WithWords(BoolOption("texture", d.texture, "add the matched fragments' high bands to keyed joints"), "on", "off"),
      WithWords(BoolOption("repin_keys", d.repin_keys, "restore the exact keys after texturing"), "on", "off"),
      IntOption("candidates", d.candidates, 1, 1024, "best database fragments kept per sketch fragment"),
      IntOption("blend", d.blend, 1, 1024, "candidates averaged per fragment (1 = the joined one alone; at most candidates)"),
      NumberOption("local_ridge", d.local_ridge, 0.0, false, 100.0, "",
                   "blend each fragment's candidates by local linear regression on their matching features, with "
                   "this ridge relative to their spread (0 = plain weighted average)"),
      NumberOption("limb_reach", d.limb_reach, 0.0, false, 1.0, "",
                   "move each synthesised arm this share of the way from where the blended rotations put its hand "
                   "to where the blended takes have it (0 = as the rotations put it)"),
      IntOption("consensus", d.consensus_iterations, 0, 100,
                "hierarchical: steps moving each upper-body group's blend towards the posture its candidates agree "
                "on over the take, their geometric median (0 = the blend as regressed)"),
      NumberOption("lead_detail", d.lead_detail, 0.0, false, 2.0, "",
                   "hierarchical: share of the joined take's finest detail put back into each upper-body group's "
                   "blend, which averages it away (0 = the blend's smooth curves)"),
      NumberOption("swing_gain", d.swing_gain, 0.0, false, 3.0, "",
                   "hierarchical: scale of each synthesised joint's swing about its 1 s moving average, which the "
                   "blend's candidates, a little out of phase, partly cancel (1 = the blend as it is)"),
      StringOption("match", "lowpass", {"lowpass", "band"},
                   "matching signal: lowpass (sketch-filtered curves) or band (band-pass only)"),
      WithFlag(NumberOption("context_fraction", d.context_fraction, 0.0, false, 2.0, "",
                        "matching window beyond each fragment, share of its length per side"),
           "context"),
      WithFlag(IntOption("max_drivers", d.max_drivers, 0, 1000, "hierarchical: driving joints per group (0 = all available)"),
           "drivers"),
      IntOption("leg_drivers", d.leg_drivers, 0, 1000,
                "hierarchical: driving joints of each synthesised leg, the keyed root first (0 = as --drivers)"),
      WithFlag(IntOption("db_phases", d.db_phases, 0, 1000, "key phases of the sketch-filtered database (0 = all)"), "phases"),
      WithFlag(IntOption("match_samples", d.match_samples, 2, 64, "samples per driven channel after time-stretching"),
           "samples"),
      WithFlag(NumberOption("fragment_band_hz", d.fragment_band_hz, 0.01, false, 100.0, "Hz",
                        "peak frequency of the fragmentation band"),
           "fragment-hz"),
      NumberOption("root_weight", d.root_feature_weight, 0.0, false, 100.0, "", "weight of the root features among the drivers"),
      WithFlag(NumberOption("travel_weight", d.travel_weight, 0.0, false, 100.0, "",
                            "hierarchical: how many times more each group's matching weighs the root's planar velocity (stance feet move with it, arms swing with the pace)"),
               "travel"),
      WithFlag(NumberOption("moving_travel_weight", d.moving_travel_weight, 0.0, false, 100.0, "",
                            "hierarchical, sketches that key the legs: --travel for the upper body where the root "
                            "moves faster than 0.6 m/s (the keyed legs carry the gait)"),
               "travel-moving"),
      NumberOption("crossfade", d.crossfade, 0.0, false, 2.0, "",
                   "overlap of neighbouring fragments (share of their length) cross-faded instead of seam smoothing"),
      WithWords(BoolOption("root_drives", d.root_drives, "hierarchical: the keyed root's tilt always drives"), "true", "false"),
      WithFlag(NumberOption("synthesized_driver_weight", d.synthesized_driver_weight, 0.0, false, 10.0, "",
                        "hierarchical: weight of already synthesised joints as drivers (keyed = 1)"),
           "synth-weight"),
      IntOption("threads", d.threads, 0, 256, "matching threads (0 = all cores)"),
      WithFlag(WithWords(BoolOption("blend_poor_coverage", d.coverage.blend,
                            "stretches the database covers poorly: blend their synthesised joints towards the prior "
                            "(blend), or only report them (warn)"),
                 "blend", "warn"),
           "coverage"),
      StringOption("coverage_prior", "mean", {"mean", "nn"},
                   "what poorly covered stretches blend towards: mean (database mean pose) or nn (nearest pose)"),
      NumberOption("coverage_poor", d.coverage.poor_share, 0.001, false, 0.999, "",
                   "poorly covered where the nearest database match leaves at least this share of the keyed motion "
                   "unexplained"),
      NumberOption("coverage_none", d.coverage.none_share, 0.002, false, 1.0, "",
                   "not covered at all (the prior alone) from this unexplained share on (above coverage_poor)"),
      StringOption("pca_fit", "subspace", {"subspace", "full-pose"},
                   "hybrid: PCA fit variant, subspace (keys within key_deg, then re-pinned) or full-pose (keys exact; "
                   "slower)"),
      NumberOption("guide_deg", pca.fit.fit.guide_sigma_deg, 0.01, false, 1000.0, "deg",
                   "hybrid: tolerance of the guide towards the fragment result"),
      NumberOption("key_deg", pca.fit.fit.key_sigma_deg, 0.001, false, 100.0, "deg",
                   "hybrid: tolerance of rotation keys in the fit"),
      NumberOption("variance", pca.model.basis.variance_kept, 0.01, false, 1.0, "",
                   "PCA model built from the database: share of the variance kept"),
      IntOption("max_components", pca.model.basis.max_components, 1, 1000,
                "PCA model built from the database: at most this many components"),
      StringOption("keyed_base", "fit", {"fit", "sketch"},
                   "hybrid: keyed joints' low bands from the PCA fit or the sketch"),
      WithFlag(WithWords(BoolOption("texture_synthesized", pca.texture_synthesized,
                            "hybrid: add the fragments' high bands to synthesised joints too"),
                 "on", "off"),
           "texture-synth"),
      WithBounds(ListOption("gains", OptionType::kNumberList, "hybrid edit: band gains after the fill, L0 (highest) first"),
              0.0, 10.0),
      ListOption("dial", OptionType::kNumberMap,
                 "hybrid edit: move PCA component <k> (1-based) by <s> standard deviations, e.g. 1=+1.5"),
  };
}

std::vector<OptionSpec> SketchFillOptionSpecs() {
  std::vector<OptionSpec> specs = {
      WithFlag(ListOption("rename", OptionType::kStringMap,
                      "rig map overrides: sketch joint -> canonical bone or database joint, e.g. {\"Hip\": \"hips\"} "
                      "(\"\" leaves a joint unmapped)"),
           "map"),
      WithCheck(StringOption("rest", "auto", RestSourceNames(),
                           "the sketch rig's rest pose: auto (bind pose of a skin, else zero pose, else the sketch's "
                           "mean pose, else its first frame)"),
              [](const OptionValue& v) { return ParseRestSource(v.text).status(); }),
      WithFlag(NumberOption("rate_hz", 0.0, 0.0, false, 1000.0, "Hz", "output rate (0 = the sketch's own)"), "rate"),
      ListOption("keep", OptionType::kStringList, "only these joints stay keyed; every other joint is synthesised"),
      ListOption("synthesize", OptionType::kStringList, "joints synthesised even when keyed"),
      ListOption("position_keys", OptionType::kStringList,
                 "joints whose translation keys are world-space position targets (hybrid method)"),
      WithFlag(WithWords(BoolOption("plant_feet", SketchFillOptions{}.plant_feet,
                            "a foot standing low and still at two consecutive keys is held there in between (leg "
                            "IK; keys stay exact): plant, or free (legs as filled)"),
                 "plant", "free"),
           "feet"),
  };
  for (OptionSpec& spec : FillMethodOptionSpecs()) specs.push_back(std::move(spec));
  return specs;
}

Result<FillOptions> FillOptionsFrom(const NodeOptions& o, const std::function<std::string(const std::string&)>& label) {
  FillOptions options;
  options.method = *ParseFillMethod(o.String("method"));
  options.join = *ParseJoinCriterion(o.String("join"));
  options.texture = o.Bool("texture");
  options.repin_keys = o.Bool("repin_keys");
  options.candidates = o.Int("candidates");
  // A smaller candidate list caps the blend.
  options.blend = std::min(o.Int("blend"), options.candidates);
  options.match_signal = o.String("match") == "band" ? MatchSignal::kBand : MatchSignal::kLowPass;
  options.context_fraction = o.Number("context_fraction");
  options.max_drivers = o.Int("max_drivers");
  options.db_phases = o.Int("db_phases");
  options.match_samples = o.Int("match_samples");
  options.fragment_band_hz = o.Number("fragment_band_hz");
  options.root_feature_weight = o.Number("root_weight");
  options.travel_weight = o.Number("travel_weight");
  options.moving_travel_weight = o.Number("moving_travel_weight");
  options.crossfade = o.Number("crossfade");
  options.local_ridge = o.Number("local_ridge");
  options.limb_reach = o.Number("limb_reach");
  options.consensus_iterations = o.Int("consensus");
  options.lead_detail = o.Number("lead_detail");
  options.swing_gain = o.Number("swing_gain");
  options.root_drives = o.Bool("root_drives");
  options.leg_drivers = o.Int("leg_drivers");
  options.synthesized_driver_weight = o.Number("synthesized_driver_weight");
  options.threads = o.Int("threads");
  options.coverage.blend = o.Bool("blend_poor_coverage");
  options.coverage.prior = o.String("coverage_prior") == "nn" ? CoveragePrior::kNearest : CoveragePrior::kMean;
  options.coverage.poor_share = o.Number("coverage_poor");
  options.coverage.none_share = o.Number("coverage_none");
  PcaMethodOptions& pca = options.pca;
  pca.fit.full_pose = o.String("pca_fit") == "full-pose";
  pca.fit.fit.guide_sigma_deg = o.Number("guide_deg");
  pca.fit.fit.key_sigma_deg = o.Number("key_deg");
  pca.model.basis.variance_kept = o.Number("variance");
  pca.model.basis.max_components = o.Int("max_components");
  pca.keyed_base = o.String("keyed_base") == "sketch" ? KeyedBase::kSketch : KeyedBase::kFit;
  pca.texture_synthesized = o.Bool("texture_synthesized");
  pca.band_gains = o.NumberList("gains");
  ASSIGN_OR_RETURN(pca.dials, DialsOf(o.NumberMap("dial"), FillOptionLabel(label, "dial")));
  RETURN_IF_ERROR(options.Validate());
  return options;
}

Result<SketchFillOptions> SketchFillOptionsFrom(const NodeOptions& o,
                                                const std::function<std::string(const std::string&)>& label) {
  SketchFillOptions options;
  ASSIGN_OR_RETURN(options.fill, FillOptionsFrom(o, label));
  options.map = o.StringMap("rename");
  options.rest = *ParseRestSource(o.String("rest"));
  options.output_rate_hz = o.Number("rate_hz");
  options.keep = o.StringList("keep");
  options.synthesize = o.StringList("synthesize");
  options.position_keys = o.StringList("position_keys");
  options.plant_feet = o.Bool("plant_feet");
  return options;
}

}  // namespace mocapfill::graph
