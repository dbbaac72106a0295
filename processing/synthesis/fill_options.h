// Options and report of the fill stage (issue #4; algorithms.md sections 3, 4 and 9.3): which
// method completes the missing joints of a sketch, how fragments are matched and joined, and
// what the report tells the user about where every synthesised stretch came from.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "processing/core/status.h"
#include "processing/pca/pca_edit.h"
#include "processing/pca/pca_model_builder.h"
#include "processing/pca/pca_sketch.h"

namespace mocapfill {

enum class FillMethod {
  kMean,          // B1: keyed joints as sketched, missing joints at the database mean pose
  kNearest,       // B3: per key frame the nearest database pose in the keyed channels
  kFragment,      // B5: fragment synthesis, all missing joints one target set (section 3)
  kHierarchical,  // B6: fragment synthesis outward from the keyed joints (section 4)
  kPca,           // B4: closed-form regularised PCA fit per frame (5a.6)
  kHybrid,        // B7: hierarchical fragments, Ceres PCA fit guided by them, texture, edits (section 7)
};

// What a keyed channel's low bands come from in the hybrid's texturing stage.
enum class KeyedBase {
  kFit,     // the PCA fit (keys within s_key, smooth in between by the prior)
  kSketch,  // the sketch interpolated between its keys (as the hierarchical method)
};

// Options of the PCA-based methods (`pca`, `hybrid`; algorithms.md 5-7). Units in the names.
struct PcaMethodOptions {
  // Model built in memory from the fill database when the caller gives none (FillEngine::
  // SetPcaModel): pose PCA, 95 % of the variance, at most 30 components (5b).
  PcaModelOptions model;
  ClosedFormOptions closed_form;  // `pca`: observation noise of keyed channels (1 deg)
  // `hybrid` stage 2: the Ceres fit, guided towards the fragment result. Default: the subspace
  // variant (keys within s_key, re-pinned after texturing) with s_guide = 3 deg. Measured,
  // leave-one-style-out on all 174 Bandai-Namco clips (docs/fill.md): locomotion upper-body
  // MPJPE 7.172 cm (hierarchical 7.181), fit about 40 ms; s_guide 10 deg gave 7.368 cm. The
  // full-pose variant (fit.full_pose = true: keyed joints held exactly, all others free under
  // the PPCA prior; s_guide 10) scores better on gestures (10.92 vs 11.12 cm, NPSS 0.046 vs
  // 0.051) but its solve takes about 0.6 s of the 1.5 s budget on the shipped 10 s sketch.
  // s_pos = 0.1 cm: against the guide and a small model, 0.25 cm left keyed feet 1.16 cm off
  // (shipped sketch, default database, subspace); 0.1 cm gives 0.52 cm (full-pose 0.21 cm).
  PcaSketchFitOptions fit = [] {
    PcaSketchFitOptions o;
    o.fit.guide_sigma_deg = 3.0;
    o.fit.position_sigma_cm = 0.1;
    return o;
  }();
  // `hybrid` stage 3: texture bands of the fragment result added to every synthesised
  // channel too (not only keyed ones), so the PCA prior does not smooth capture detail away.
  bool texture_synthesized = true;
  KeyedBase keyed_base = KeyedBase::kFit;
  // `hybrid` stage 4 (optional edits, applied last; keys are not re-pinned after them):
  std::vector<double> band_gains;    // Bruderlin-Williams gains, band 0 first; empty = none
  std::vector<ComponentDial> dials;  // PCA component dials in standard deviations

  Status Validate() const;
};

// How one candidate per fragment is chosen (thesis 4.6, algorithms.md 3a.4).
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

struct FillOptions {
  FillMethod method = FillMethod::kHierarchical;
  JoinCriterion join = JoinCriterion::kCostMatrix;
  MatchSignal match_signal = MatchSignal::kLowPass;
  bool texture = true;      // add the chosen fragments' high bands to keyed channels
  bool repin_keys = true;   // restore the exact keys after texturing (displacement map)
  int candidates = 128;     // K best candidates kept per fragment
  int blend = 128;          // candidates averaged per fragment (1 = the joined one alone)
  double fragment_band_hz = 1.0;  // master band by its peak frequency (L3 at 30 Hz: stride)
  double match_band_hz = 1.0;     // matching band for MatchSignal::kBand
  int match_samples = 8;          // samples per driven channel after time-stretching
  double context_fraction = 0.5;  // matching window extends each fragment by this share per side
  double min_length_ratio = 0.67;  // accepted database/sketch fragment length ratios
  double max_length_ratio = 1.5;
  double seam_window_s = 0.25;     // seam smoothing reach on each side
  double crossfade = 1.0;          // > 0: fragments overlap by this share of their length and are cross-faded
  double transition_gamma = 0.5;   // cost matrix: weight of the velocity jump at seams
  int max_drivers = 3;             // hierarchical: driven joints per group (0 = all available)
  bool root_drives = false;        // hierarchical: the keyed root's tilt always among the drivers
  double synthesized_driver_weight = 1.0;  // weight of already synthesised drivers (keyed = 1)
  double root_feature_weight = 1.0;        // weight of the root features among the drivers
  int db_phases = 0;   // key phases of the sketch-filtered database (0 = every phase)
  int threads = 0;     // matching threads (0 = hardware concurrency)
  CoverageOptions coverage;
  PcaMethodOptions pca;  // `pca` and `hybrid` methods only

  // Fails with kInvalidArgument naming the field, its value and the allowed range.
  Status Validate() const;
};

// Names used on the command line and in reports: "mean", "nn", "fragment", "hierarchical";
// "best-fragment", "cost-matrix", "best-animation"; "band", "lowpass"; "pca", "hybrid".
const char* FillMethodName(FillMethod method);
const char* JoinCriterionName(JoinCriterion join);
Result<FillMethod> ParseFillMethod(std::string_view text);
Result<JoinCriterion> ParseJoinCriterion(std::string_view text);

// Where one synthesised stretch came from.
struct FragmentSource {
  std::string group;        // joint group, e.g. "Shoulder_L..Hand_L"
  int first_frame = 0;      // sketch frames [first_frame, last_frame]
  int last_frame = 0;
  std::string clip;         // database clip of the joined (lead) candidate
  int clip_first_frame = 0;
  int clip_last_frame = 0;
  double distance = 0.0;    // matching distance of that candidate
  int blended = 1;          // candidates averaged into the stretch
};

// How well the database covers one sketch fragment.
struct FragmentCoverage {
  int first_frame = 0;  // sketch frames [first_frame, last_frame]
  int last_frame = 0;
  double distance = 0.0;      // squared matching distance of the nearest database fragment
  double unexplained = 0.0;   // distance / squared distance to the mean pose standing still
  double takes_ratio = -1.0;  // sqrt(distance) / the database's own takes' (< 0: one clip only)
  double prior_weight = 0.0;    // share of the prior blended into its synthesised channels
  double texture_weight = 0.0;  // share of the texture taken off its keyed channels
};

// Consecutive fragments at or above CoverageOptions::poor_share.
struct PoorlyCoveredStretch {
  int first_frame = 0;
  int last_frame = 0;
  double worst_unexplained = 0.0;
  double worst_takes_ratio = -1.0;
  double max_prior_weight = 0.0;
};

struct CoverageReport {
  bool measured = false;            // fragment methods only
  double reference_distance = 0.0;  // median nearest other-take distance (not squared); 0: one clip
  double poor_share = 0.0;          // the options' thresholds, for readers of the report
  double none_share = 0.0;
  double texture_poor_share = 0.0;
  double texture_none_share = 0.0;
  std::string prior;                // "mean", "nn"; empty when blending is off
  std::vector<FragmentCoverage> fragments;
  std::vector<PoorlyCoveredStretch> poor;
};

struct JointFillInfo {
  std::string name;
  std::string kind;               // "keyed", "textured" or "synthesized"
  int keys = 0;                   // rotation keys in the sketch
  double key_error_mean_deg = 0.0;  // output vs key at the keyed frames
  double key_error_max_deg = 0.0;
};

struct StageTime {
  std::string stage;
  double seconds = 0.0;
};

struct FillReport {
  std::string method;
  std::string join;
  int frames = 0;
  double rate_hz = 0.0;
  int key_spacing_frames = 0;     // median spacing of the sketch's keys
  std::string master_channel;     // fragmentation channel
  int fragment_band = -1;
  int sketch_fragments = 0;
  int seams = 0;                  // fragment boundaries where the lead candidate switches take
  double key_error_mean_deg = 0.0;
  double key_error_max_deg = 0.0;
  std::vector<JointFillInfo> joints;
  std::vector<FragmentSource> fragments;
  std::vector<StageTime> stages;
  std::vector<std::string> group_order;  // hierarchical: groups in synthesis order with drivers
  CoverageReport coverage;
  // PCA methods: where the model came from ("given" or "built from the database"), its size,
  // and (hybrid) the Ceres summary of the key fit.
  std::string pca_model_source;
  int pca_components = 0;
  bool has_solver = false;
  SolverReport solver;
};

}  // namespace mocapfill
