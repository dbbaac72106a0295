#include "converter/fill_flags.h"

#include <algorithm>
#include <stdexcept>

#include "converter/option_values.h"

namespace mocapfill::cli {

void AddFillFlags(CLI::App& command, FillOptions& options, FillFlagText& text) {
  command.add_option("--join", text.join, "Joining criterion: cost-matrix, best-fragment or best-animation")
      ->check(CLI::IsMember({"cost-matrix", "best-fragment", "best-animation"}))
      ->capture_default_str();
  command.add_option("--texture", text.texture, "Add the matched fragments' high bands to keyed joints: on or off")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  command.add_option("--candidates", options.candidates, "K best database fragments kept per sketch fragment")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  command.add_option("--blend", options.blend, "Candidates averaged per fragment (1 = the joined one alone; at most --candidates)")
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  command.add_option("--match", text.match, "Matching signal: lowpass (sketch-filtered curves) or band (band-pass only)")
      ->check(CLI::IsMember({"lowpass", "band"}))
      ->capture_default_str();
  command.add_option("--context", options.context_fraction, "Matching window beyond each fragment, share of its length per side")
      ->check(CLI::Range(0.0, 2.0))
      ->capture_default_str();
  command.add_option("--drivers", options.max_drivers, "Hierarchical: driven joints per group (0 = all available)")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  command.add_option("--phases", options.db_phases, "Key phases of the sketch-filtered database (0 = all)")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  command.add_option("--samples", options.match_samples, "Samples per driven channel after time-stretching")
      ->check(CLI::Range(2, 64))
      ->capture_default_str();
  command.add_option("--fragment-hz", options.fragment_band_hz, "Fragmentation band, by its peak frequency (Hz)")
      ->check(CLI::Range(0.01, 100.0))
      ->capture_default_str();
  command.add_option("--root-weight", options.root_feature_weight, "Weight of the root features among the drivers")
      ->check(CLI::Range(0.0, 100.0))
      ->capture_default_str();
  command.add_option("--crossfade", options.crossfade,
                     "Overlap of neighbouring fragments (share of their length) cross-faded instead of seam smoothing")
      ->check(CLI::Range(0.0, 2.0))
      ->capture_default_str();
  command.add_option("--root-drives", options.root_drives, "Hierarchical: the keyed root's tilt always drives")
      ->capture_default_str();
  command.add_option("--synth-weight", options.synthesized_driver_weight,
                     "Hierarchical: weight of already synthesised joints as drivers (keyed = 1)")
      ->check(CLI::Range(0.0, 10.0))
      ->capture_default_str();
  command.add_option("--threads", options.threads, "Matching threads (0 = all cores)")
      ->check(CLI::Range(0, 256))
      ->capture_default_str();
  command.add_option("--coverage", text.coverage,
                     "Stretches the database covers poorly: blend (their synthesised joints towards the prior) or "
                     "warn (only report them)")
      ->check(CLI::IsMember({"blend", "warn"}))
      ->capture_default_str();
  command.add_option("--coverage-prior", text.coverage_prior,
                     "What poorly covered stretches blend towards: mean (database mean pose) or nn (nearest pose)")
      ->check(CLI::IsMember({"mean", "nn"}))
      ->capture_default_str();
  command.add_option("--coverage-poor", options.coverage.poor_share,
                     "Poorly covered where the nearest database match leaves at least this share of the keyed "
                     "motion unexplained")
      ->check(CLI::Range(0.001, 0.999))
      ->capture_default_str();
  command.add_option("--coverage-none", options.coverage.none_share,
                     "Not covered at all (the prior alone) from this unexplained share on (above --coverage-poor)")
      ->check(CLI::Range(0.002, 1.0))
      ->capture_default_str();
}

void AddPcaMethodFlags(CLI::App& command, FillOptions& options, FillFlagText& text) {
  PcaMethodOptions& pca = options.pca;
  command.add_option("--pca-fit", text.pca_fit,
                     "Hybrid: PCA fit variant, subspace (keys within --key-deg, then re-pinned) or full-pose (keys exact; slower)")
      ->check(CLI::IsMember({"subspace", "full-pose"}))
      ->capture_default_str();
  command.add_option("--guide-deg", pca.fit.fit.guide_sigma_deg,
                     "Hybrid: tolerance of the guide towards the fragment result (degrees)")
      ->check(CLI::Range(0.01, 1000.0))
      ->capture_default_str();
  command.add_option("--key-deg", pca.fit.fit.key_sigma_deg, "Hybrid: tolerance of rotation keys in the fit (degrees)")
      ->check(CLI::Range(0.001, 100.0))
      ->capture_default_str();
  command.add_option("--variance", pca.model.basis.variance_kept,
                     "PCA model built from the database: share of the variance kept")
      ->check(CLI::Range(0.01, 1.0))
      ->capture_default_str();
  command.add_option("--max-components", pca.model.basis.max_components,
                     "PCA model built from the database: at most this many components")
      ->check(CLI::Range(1, 1000))
      ->capture_default_str();
  command.add_option("--keyed-base", text.keyed_base,
                     "Hybrid: keyed joints' low bands from the PCA fit or the sketch (fit or sketch)")
      ->check(CLI::IsMember({"fit", "sketch"}))
      ->capture_default_str();
  command.add_option("--texture-synth", text.texture_synthesized,
                     "Hybrid: add the fragments' high bands to synthesised joints too (on or off)")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  command.add_option("--gains", pca.band_gains,
                     "Hybrid edit: band gains after the fill, L0 (highest) first, comma-separated")
      ->delimiter(',')
      ->check(CLI::Range(0.0, 10.0));
  command.add_option("--dial", text.dials,
                     "Hybrid edit: move PCA component <k> (1-based) by <s> standard deviations, e.g. --dial 1=+1.5")
      ->delimiter(',');
}

Status ApplyFillFlagText(const FillFlagText& text, FillOptions& options) {
  ASSIGN_OR_RETURN(options.join, ParseJoinCriterion(text.join));
  options.texture = text.texture == "on";
  options.coverage.blend = text.coverage == "blend";
  options.coverage.prior = text.coverage_prior == "nn" ? CoveragePrior::kNearest : CoveragePrior::kMean;
  options.match_signal = text.match == "band" ? MatchSignal::kBand : MatchSignal::kLowPass;
  options.blend = std::min(options.blend, options.candidates);  // a smaller K caps the blend
  options.pca.fit.full_pose = text.pca_fit == "full-pose";
  options.pca.keyed_base = text.keyed_base == "sketch" ? KeyedBase::kSketch : KeyedBase::kFit;
  options.pca.texture_synthesized = text.texture_synthesized == "on";
  ASSIGN_OR_RETURN(options.pca.dials, ParseComponentDials(text.dials, "--dial"));
  return OkStatus();
}

}  // namespace mocapfill::cli
