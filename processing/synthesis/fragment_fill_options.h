// Options of the fragment methods and the baselines (thesis chapter 4):
// which method completes the missing joints of a sketch, and how fragments are matched, joined
// and blended where the database covers the sketch poorly. The fill's options
// (processing/fill/fill_options.h) add those of the PCA-based methods.
#pragma once

#include <string_view>

#include "processing/core/status.h"

namespace mocapfill {

// Every method of the fill, so that one option names the choice: synthesis runs the first
// four (FragmentFillEngine), the fill engine (processing/fill) the PCA-based two.
enum class FillMethod {
  kMean,          // B1: keyed joints as sketched, missing joints at the database mean pose
  kNearest,       // B3: per key frame the nearest database pose in the keyed channels
  kFragment,      // B5: fragment synthesis, all missing joints one target set (section 3)
  kHierarchical,  // B6: fragment synthesis outward from the keyed joints (section 4)
  kPca,           // B4: closed-form regularised PCA fit per frame (5a.6)
  kHybrid,        // B7: hierarchical fragments, Ceres PCA fit guided by them, texture, edits (section 7)
};

// How one candidate per fragment is chosen (thesis 4.6).
enum class JoinCriterion {
  kBestFragment,   // the nearest candidate of every fragment (greedy)
  kCostMatrix,     // Viterbi over candidates with transition costs at the seams
  kBestAnimation,  // one database clip wherever it has a candidate, cost matrix elsewhere
};

// Which signal of the driven channels fragments are compared on.
enum class MatchSignal {
  kBand,     // the matching band L_km only (ignores constant offsets: keyframed vs captured)
  kLowPass,  // the sketch-filtered signal itself (keeps posture offsets; captured sketches)
};

// What a poorly covered stretch is blended towards.
enum class CoveragePrior {
  kMean,     // the database mean pose (method `mean`)
  kNearest,  // the database pose nearest the keys (method `nn`)
};

// Coverage of the sketch by the database (fragment methods; coverage.h). A sketch fragment's
// score is its unexplained share: the squared distance of its nearest database fragment on
// the keyed channels over its squared distance to the database mean pose standing still (how
// much of the motion the best match leaves unexplained). From `poor_share` on, a stretch is
// reported as poorly covered and its synthesised channels are blended towards the prior,
// fully at `none_share`. The captured detail that texturing adds to keyed channels fades
// earlier, between the texture thresholds (detail of another motion made the keyed feet of
// standing sketches slide: docs/fill.md, Coverage).
struct CoverageOptions {
  bool blend = true;  // false: only report
  CoveragePrior prior = CoveragePrior::kMean;
  double poor_share = 0.04;
  double none_share = 0.08;
  double texture_poor_share = 0.02;
  double texture_none_share = 0.04;
  int reference_fragments = 128;  // database fragments sampled for the takes yardstick (a median)
};

struct FragmentFillOptions {
  FillMethod method = FillMethod::kHierarchical;
  JoinCriterion join = JoinCriterion::kCostMatrix;
  MatchSignal match_signal = MatchSignal::kLowPass;
  bool texture = true;      // add the chosen fragments' high bands to keyed channels
  // Texture bands start here: 1 leaves out the finest (above 7.5 Hz at 30 Hz), another take's
  // foot impacts and tremor, which made the fill jerkier than capture (texture_channels.h).
  int texture_finest_band = 1;
  // Synthesised channels lose this many finest bands (1: above 7.5 Hz at 30 Hz) after assembly:
  // there the blend holds its own jolts, not captured detail of this motion.
  int synthesized_finest_band = 1;
  bool repin_keys = true;   // restore the exact keys after texturing (displacement map)
  // K best candidates kept per fragment, and how many of them are averaged (1 = the joined one
  // alone). More averaged candidates smooth locomotion's upper body towards what the takes
  // agree on, fewer keep a gesture's own posture: 160 is where both gain (docs/fill.md).
  int candidates = 160;
  int blend = 160;
  int leg_blend = 32;       // hierarchical: at most this many for chains hanging below the root (legs)
  // > 0: the blend is a local linear regression over the candidates (local_regression.h) with
  // this ridge, relative to the candidates' spread; 0: their plain weighted average.
  double local_ridge = 0.3;
  // Share of the way each synthesised arm moves from where the blended rotations put its hand
  // to where the blended takes have it (limb_reach.h); 0: as the rotations put it.
  double limb_reach = 0.5;
  // Hierarchical: Weiszfeld steps moving each upper-body group's blend from the mean of its
  // candidates' postures towards their geometric median over the take (consensus_weights.h);
  // 0: the blend weights as matched and regressed. Candidates within consensus_floor_m of the
  // consensus keep their weight.
  int consensus_iterations = 25;
  double consensus_floor_m = 0.05;
  // Hierarchical: the upper-body groups get back this share of their lead candidate's finest
  // bands (those synthesized_finest_band takes off the blend): the average of many takes cancels
  // their detail (its jerk was 0.54 - 0.67 of the capture's), one take has it; 0: none.
  double lead_detail = 0.7;
  // Hierarchical: each synthesised joint's swing about its 1 s moving average is scaled by this
  // (swing_gain.h): the blend's candidates swing out of phase with each other and partly cancel;
  // 1: the blend as it is (so is a single take, blend 1).
  double swing_gain = 1.2;
  // Hierarchical: where the keyed root moves, a synthesised leg's candidates whose hips sway
  // over the other foot than the sketch's count as this much farther (distance times
  // 1 + weight * (1 - agreement) / 2, agreement the cosine of the sways; gait_sway.h): they
  // stepped in anti-phase, planting a foot where the capture's swung; 0: matched without.
  double leg_sway_weight = 10.0;
  // ... in the fragments whose root moves faster than this: slow walks (0.45 - 0.6 m/s) sway
  // as clearly as brisk ones and stepped in anti-phase as often; below it a standing sketch's
  // sway is noise.
  double sway_speed_m_per_s = 0.45;
  double fragment_band_hz = 1.0;  // master band by its peak frequency (L3 at 30 Hz: stride)
  double match_band_hz = 1.0;     // matching band for MatchSignal::kBand
  int match_samples = 8;          // samples per driven channel after time-stretching
  double context_fraction = 0.0;  // matching window extends each fragment by this share per side
  double min_length_ratio = 0.67;  // accepted database/sketch fragment length ratios
  double max_length_ratio = 1.5;
  // Where the sketch keys no leg, matching (and the blend's regression) compares the root's
  // velocities as each take moves them once stretched onto the sketch's fragment
  // (StretchSpeedRatio, fragment_matching.h), the pace its synthesised feet step at. Keyed legs
  // carry the sketch's pace themselves, and there it did not win (docs/fill.md, step 4).
  // false: as captured everywhere.
  bool stretched_travel = true;
  double seam_window_s = 0.25;     // seam smoothing reach on each side
  double crossfade = 1.5;          // > 0: fragments overlap by this share of their length and are cross-faded
  double transition_gamma = 0.5;   // cost matrix: weight of the velocity jump at seams
  int max_drivers = 3;             // hierarchical: driven joints per group (0 = all available)
  bool root_drives = false;        // hierarchical: the keyed root's tilt always among the drivers
  // Hierarchical: driving joints of each leg chain (those hanging below the root), the keyed
  // root first; 0: as the other groups. The pelvis carries the thighs, but its tilt ranked
  // below the torso's joints in the correlation table, so the legs were matched on a torso
  // that bends with the arms rather than on the hips they hang from.
  int leg_drivers = 2;
  double synthesized_driver_weight = 1.0;  // weight of already synthesised drivers (keyed = 1)
  double root_feature_weight = 1.0;        // weight of the root features among the drivers
  // Hierarchical: each group's drivers weigh the root's planar velocity this many times more.
  double travel_weight = 6.0;
  // ... but where the sketch keys the legs, an upper-body group weighs it this many times in the
  // fragments whose root moves faster than moving_speed_m_per_s: the keyed legs carry the gait,
  // and matching the pace as well drew the arms from takes of another gait.
  double moving_travel_weight = 1.0;
  double moving_speed_m_per_s = 0.6;
  // Between two keys of the root that have it still (planar speed below this, a standing
  // foot's), the keyed travel keeps its keys' low band, without the lead's detail; 0: never.
  double still_root_m_per_s = 0.02;
  // Keyed joints of the upper body take their texture's detail scaled down where the sketch
  // moves them less than the take lending it does, both seen through the keys, over this window
  // (texturing/activity_gain.h): a timid wave took a lively take's tremor; 0: detail unscaled.
  double texture_activity_window_s = 1.0;
  int db_phases = 0;   // key phases of the sketch-filtered database (0 = every phase)
  int threads = 0;     // matching threads (0 = hardware concurrency)
  CoverageOptions coverage;

  // Fails with kInvalidArgument naming the field, its value and the allowed range.
  Status Validate() const;
};

// Names used on the command line and in reports: "mean", "nn", "fragment", "hierarchical";
// "best-fragment", "cost-matrix", "best-animation"; "band", "lowpass"; "pca", "hybrid".
const char* FillMethodName(FillMethod method);
const char* JoinCriterionName(JoinCriterion join);
Result<FillMethod> ParseFillMethod(std::string_view text);
Result<JoinCriterion> ParseJoinCriterion(std::string_view text);

}  // namespace mocapfill
