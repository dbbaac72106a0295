// The report of the fragment methods and the baselines: where every synthesised stretch came
// from, how well the database covers the sketch, what became of each joint and its keys, and
// the time per stage.
#pragma once

#include <string>
#include <vector>

namespace mocapfill {

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
  // Planar speed of the root in the blended takes over their matched frames, weighted as they
  // are blended (m/s): beside the sketch's own it tells whether the fill drew on takes that
  // travel as the sketch does (legs from standing takes slide under a walking root).
  double travel_mps = 0.0;
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

// Ground contacts of one synthesised joint (a foot or toe), voted from the matched takes'
// own contacts (ground_contacts.h), or of a textured keyed one, its texture's take's; the
// planter holds the joint over them.
struct FrameRun {
  int first_frame = 0;  // fill frames [first_frame, last_frame]
  int last_frame = 0;
};

struct SynthesizedContacts {
  std::string joint;
  int joint_index = -1;  // in the database's skeleton
  std::vector<FrameRun> runs;
  double ground_height_m = 0.0;  // where the database's takes stand this joint (world up, metres)
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

// The report of a fill by a fragment method or a baseline. The fill's report
// (processing/fill/fill_report.h) adds what the PCA-based methods report.
struct FragmentFillReport {
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
  // Every synthesised joint that stands in the database, and every keyed one (the legs) that
  // stands in its texture's take.
  std::vector<SynthesizedContacts> contacts;
};

}  // namespace mocapfill
