#include "converter/fill_flags.h"

#include <algorithm>

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
}

Status ApplyFillFlagText(const FillFlagText& text, FillOptions& options) {
  ASSIGN_OR_RETURN(options.join, ParseJoinCriterion(text.join));
  options.texture = text.texture == "on";
  options.match_signal = text.match == "band" ? MatchSignal::kBand : MatchSignal::kLowPass;
  options.blend = std::min(options.blend, options.candidates);  // a smaller K caps the blend
  return OkStatus();
}

}  // namespace mocapfill::cli
