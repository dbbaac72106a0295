#include "formats/assimp/assimp_fixups.h"

#include <algorithm>
#include <cmath>

namespace mocapfill::assimp_detail {

namespace {

// Relative spread under which a scale counts as uniform (FBX files carry float noise
// such as 100, 99.999992, 99.999992).
constexpr double kUniformScaleTolerance = 1e-5;

// The uniform factor of a positive, (nearly) uniform scale, or nullopt.
std::optional<double> UniformFactor(const Eigen::Vector3d& s) {
  const double lo = s.minCoeff(), hi = s.maxCoeff();
  if (!(lo > 1e-12) || hi - lo > kUniformScaleTolerance * hi) return std::nullopt;
  return s.mean();
}

}  // namespace

DetectedRate DetectKeyRateHz(const std::vector<double>& key_times_s) {
  for (double rate : kCandidateRatesHz) {
    const bool fits = std::all_of(key_times_s.begin(), key_times_s.end(), [rate](double t) {
      return std::abs(t - std::round(t * rate) / rate) <= kKeyGridToleranceS;
    });
    if (fits) return {rate, true};
  }
  return {kFallbackRateHz, false};
}

std::optional<VertexInfluences> TopFourInfluences(std::vector<std::pair<int, float>> influences) {
  // Merge repeated slots (two bones naming one joint), dropping unusable weights.
  std::sort(influences.begin(), influences.end());
  std::vector<std::pair<int, float>> merged;
  for (const auto& [slot, w] : influences) {
    if (!std::isfinite(w) || w <= 0.0f || slot < 0) continue;
    if (!merged.empty() && merged.back().first == slot) {
      merged.back().second += w;
    } else {
      merged.emplace_back(slot, w);
    }
  }
  if (merged.empty()) return std::nullopt;
  std::stable_sort(merged.begin(), merged.end(),
                   [](const auto& a, const auto& b) { return a.second > b.second; });
  const size_t kept = std::min<size_t>(4, merged.size());
  float sum = 0.0f;
  for (size_t i = 0; i < kept; ++i) sum += merged[i].second;
  VertexInfluences out;
  for (size_t i = 0; i < kept; ++i) {
    out.slots[i] = static_cast<std::uint16_t>(merged[i].first);
    out.weights[i] = merged[i].second / sum;
  }
  // The largest weight absorbs the rounding residue, so the float sum is 1 (glTF
  // validators flag sums off by more than a few ulps).
  out.weights[0] = 1.0f - (out.weights[1] + out.weights[2] + out.weights[3]);
  return out;
}

int BakeUniformJointScales(Scene& scene) {
  Skeleton& skeleton = scene.skeleton;
  const int n = skeleton.num_joints();
  std::vector<double> accumulated(n, 1.0);  // product of the baked scales of j and its ancestors
  int baked = 0;
  for (int j = 0; j < n; ++j) {
    Joint& joint = skeleton.mutable_joint(j);
    const double above = joint.parent == kNoParent ? 1.0 : accumulated[joint.parent];
    joint.rest_translation *= above;
    for (MotionClip& clip : scene.clips) {
      for (int f = 0; f < clip.num_frames; ++f) clip.translation(f, j) *= above;
      if (static_cast<size_t>(j) < clip.keys.size())
        for (Eigen::Vector3d& t : clip.keys[j].translation_values) t *= above;
    }
    accumulated[j] = above;
    if (const auto factor = UniformFactor(joint.rest_scale)) {
      accumulated[j] = above * *factor;
      joint.rest_scale = Eigen::Vector3d::Ones();
      if (*factor != 1.0) ++baked;
    }
  }
  // World transforms lose the factor on the right (B' = B * S^-1), so IBM' = S * IBM keeps
  // B' * IBM' = B * IBM, and positions in a joint's frame grow by the factor.
  for (Skin& skin : scene.skins) {
    for (size_t k = 0; k < skin.joints.size(); ++k) {
      const double a = accumulated[skin.joints[k]];
      skin.inverse_bind_matrices[k].topRows<3>() *= a;
    }
  }
  for (Mesh& mesh : scene.meshes) {
    if (mesh.skin >= 0 || mesh.attach_joint < 0) continue;
    const float a = static_cast<float>(accumulated[mesh.attach_joint]);
    for (MeshPrimitive& prim : mesh.primitives)
      for (Eigen::Vector3f& p : prim.positions) p *= a;
  }
  return baked;
}

}  // namespace mocapfill::assimp_detail
