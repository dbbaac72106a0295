// Pure helpers of the Assimp importer that need no Assimp types: frame-rate detection
// from key times, top-4 skin influence selection, and baking of uniform joint scales.
// Kept apart so they can be unit-tested on plain numbers.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "processing/core/scene.h"

namespace mocapfill::assimp_detail {

// Frame rates tried, lowest first, when the source gives key times but no sample rate.
inline constexpr double kCandidateRatesHz[] = {24, 25, 30, 48, 50, 60, 100, 120, 240};
inline constexpr double kKeyGridToleranceS = 1e-4;
inline constexpr double kFallbackRateHz = 30.0;

struct DetectedRate {
  double rate_hz = kFallbackRateHz;
  bool on_grid = false;  // false: no candidate fits, kFallbackRateHz was chosen
};

// The lowest candidate rate on whose frame grid every key time lies within kKeyGridToleranceS.
DetectedRate DetectKeyRateHz(const std::vector<double>& key_times_s);

struct VertexInfluences {
  std::array<std::uint16_t, 4> slots{0, 0, 0, 0};
  Eigen::Vector4f weights = Eigen::Vector4f::Zero();
};

// Keeps the four largest positive weights of (skin slot, weight) pairs, merging repeated
// slots first, and renormalises them so that their float sum is 1. Ties go to the lower
// slot so the result is deterministic. nullopt when no positive finite weight remains.
std::optional<VertexInfluences> TopFourInfluences(std::vector<std::pair<int, float>> influences);

// Core forward kinematics applies a joint's rest_scale to its children's offsets only,
// whereas FBX/glTF scale propagates to every descendant. Uniform scales (common on FBX
// armatures: Blender writes 100 there) are therefore moved into the data: descendants'
// rest and animated offsets, inverse bind matrices and rigid mesh positions are scaled
// so that every world position is unchanged and the joint's rest_scale becomes 1.
// Non-uniform scales stay in rest_scale. Returns the number of joints whose scale was baked.
int BakeUniformJointScales(Scene& scene);

}  // namespace mocapfill::assimp_detail
