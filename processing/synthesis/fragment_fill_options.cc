#include "processing/synthesis/fragment_fill_options.h"

#include <cmath>
#include <string>

namespace mocapfill {

namespace {

Status RangeError(const char* field, double value, const char* range) {
  return InvalidArgument(std::string(field) + ": " + std::to_string(value) + " is out of range " + range);
}

}  // namespace

Status FragmentFillOptions::Validate() const {
  if (candidates < 1 || candidates > 1024) return RangeError("candidates", candidates, "[1, 1024]");
  if (blend < 1 || blend > candidates) return RangeError("blend", blend, "[1, candidates]");
  if (leg_blend < 1) return RangeError("leg_blend", leg_blend, "[1, inf)");
  if (!(local_ridge >= 0.0 && local_ridge <= 100.0)) return RangeError("local_ridge", local_ridge, "[0, 100]");
  if (!(limb_reach >= 0.0 && limb_reach <= 1.0)) return RangeError("limb_reach", limb_reach, "[0, 1]");
  if (!(lead_detail >= 0.0 && lead_detail <= 2.0)) return RangeError("lead_detail", lead_detail, "[0, 2]");
  if (!(swing_gain >= 0.0 && swing_gain <= 3.0)) return RangeError("swing_gain", swing_gain, "[0, 3]");
  if (!(leg_sway_weight >= 0.0 && leg_sway_weight <= 1000.0))
    return RangeError("leg_sway_weight", leg_sway_weight, "[0, 1000]");
  if (!(sway_speed_m_per_s >= 0.0 && std::isfinite(sway_speed_m_per_s)))
    return RangeError("sway_speed_m_per_s", sway_speed_m_per_s, "[0, inf)");
  if (consensus_iterations < 0 || consensus_iterations > 100)
    return RangeError("consensus_iterations", consensus_iterations, "[0, 100]");
  if (!(consensus_floor_m > 0.0 && consensus_floor_m <= 1.0))
    return RangeError("consensus_floor_m", consensus_floor_m, "(0, 1]");
  if (texture_finest_band < 0 || texture_finest_band > 16)
    return RangeError("texture_finest_band", texture_finest_band, "[0, 16]");
  if (synthesized_finest_band < 0 || synthesized_finest_band > 16)
    return RangeError("synthesized_finest_band", synthesized_finest_band, "[0, 16]");
  if (!(fragment_band_hz > 0.0) || !std::isfinite(fragment_band_hz))
    return RangeError("fragment_band_hz", fragment_band_hz, "(0, inf)");
  if (!(match_band_hz > 0.0) || !std::isfinite(match_band_hz))
    return RangeError("match_band_hz", match_band_hz, "(0, inf)");
  if (match_samples < 2 || match_samples > 64) return RangeError("match_samples", match_samples, "[2, 64]");
  if (!(context_fraction >= 0.0 && context_fraction <= 2.0))
    return RangeError("context_fraction", context_fraction, "[0, 2]");
  if (!(min_length_ratio > 0.0 && min_length_ratio <= 1.0))
    return RangeError("min_length_ratio", min_length_ratio, "(0, 1]");
  if (!(max_length_ratio >= 1.0 && max_length_ratio <= 10.0))
    return RangeError("max_length_ratio", max_length_ratio, "[1, 10]");
  if (!(seam_window_s >= 0.0 && seam_window_s <= 5.0)) return RangeError("seam_window_s", seam_window_s, "[0, 5]");
  if (!(crossfade >= 0.0 && crossfade <= 2.0)) return RangeError("crossfade", crossfade, "[0, 2]");
  if (!(transition_gamma >= 0.0 && std::isfinite(transition_gamma)))
    return RangeError("transition_gamma", transition_gamma, "[0, inf)");
  if (max_drivers < 0) return RangeError("max_drivers", max_drivers, "[0, inf)");
  if (leg_drivers < 0) return RangeError("leg_drivers", leg_drivers, "[0, inf)");
  if (!(synthesized_driver_weight >= 0.0 && synthesized_driver_weight <= 10.0))
    return RangeError("synthesized_driver_weight", synthesized_driver_weight, "[0, 10]");
  if (!(root_feature_weight >= 0.0 && root_feature_weight <= 100.0))
    return RangeError("root_feature_weight", root_feature_weight, "[0, 100]");
  if (!(travel_weight >= 0.0 && travel_weight <= 100.0))
    return RangeError("travel_weight", travel_weight, "[0, 100]");
  if (!(moving_travel_weight >= 0.0 && moving_travel_weight <= 100.0))
    return RangeError("moving_travel_weight", moving_travel_weight, "[0, 100]");
  if (!(moving_speed_m_per_s >= 0.0 && std::isfinite(moving_speed_m_per_s)))
    return RangeError("moving_speed_m_per_s", moving_speed_m_per_s, "[0, inf)");
  if (!(texture_activity_window_s >= 0.0 && std::isfinite(texture_activity_window_s)))
    return RangeError("texture_activity_window_s", texture_activity_window_s, "[0, inf)");
  if (!(still_root_m_per_s >= 0.0 && std::isfinite(still_root_m_per_s)))
    return RangeError("still_root_m_per_s", still_root_m_per_s, "[0, inf)");
  if (db_phases < 0) return RangeError("db_phases", db_phases, "[0, inf)");
  if (threads < 0) return RangeError("threads", threads, "[0, inf)");
  if (!(coverage.poor_share > 0.0 && coverage.poor_share < 1.0))
    return RangeError("coverage.poor_share", coverage.poor_share, "(0, 1)");
  if (!(coverage.none_share > coverage.poor_share && coverage.none_share <= 1.0))
    return RangeError("coverage.none_share", coverage.none_share, "(poor_share, 1]");
  if (!(coverage.texture_poor_share > 0.0 && coverage.texture_poor_share < 1.0))
    return RangeError("coverage.texture_poor_share", coverage.texture_poor_share, "(0, 1)");
  if (!(coverage.texture_none_share > coverage.texture_poor_share && coverage.texture_none_share <= 1.0))
    return RangeError("coverage.texture_none_share", coverage.texture_none_share, "(texture_poor_share, 1]");
  if (coverage.reference_fragments < 8 || coverage.reference_fragments > 100000)
    return RangeError("coverage.reference_fragments", coverage.reference_fragments, "[8, 100000]");
  return OkStatus();
}

const char* FillMethodName(FillMethod method) {
  switch (method) {
    case FillMethod::kMean: return "mean";
    case FillMethod::kNearest: return "nn";
    case FillMethod::kFragment: return "fragment";
    case FillMethod::kHierarchical: return "hierarchical";
    case FillMethod::kPca: return "pca";
    case FillMethod::kHybrid: return "hybrid";
  }
  return "?";
}

const char* JoinCriterionName(JoinCriterion join) {
  switch (join) {
    case JoinCriterion::kBestFragment: return "best-fragment";
    case JoinCriterion::kCostMatrix: return "cost-matrix";
    case JoinCriterion::kBestAnimation: return "best-animation";
  }
  return "?";
}

Result<FillMethod> ParseFillMethod(std::string_view text) {
  for (FillMethod m : {FillMethod::kMean, FillMethod::kNearest, FillMethod::kFragment, FillMethod::kHierarchical,
                       FillMethod::kPca, FillMethod::kHybrid})
    if (text == FillMethodName(m)) return m;
  return InvalidArgument("unknown method '" + std::string(text) +
                         "' (expected hierarchical, fragment, nn, mean, pca or hybrid)");
}

Result<JoinCriterion> ParseJoinCriterion(std::string_view text) {
  for (JoinCriterion j : {JoinCriterion::kBestFragment, JoinCriterion::kCostMatrix, JoinCriterion::kBestAnimation})
    if (text == JoinCriterionName(j)) return j;
  return InvalidArgument("unknown join criterion '" + std::string(text) +
                         "' (expected cost-matrix, best-fragment or best-animation)");
}

}  // namespace mocapfill
