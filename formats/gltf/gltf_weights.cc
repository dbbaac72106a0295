#include "formats/gltf/gltf_weights.h"

namespace mocapfill::gltf_internal {

bool NormaliseInfluences(std::array<std::uint16_t, 4>& joints, Eigen::Vector4d& weights) {
  Eigen::Vector4d w = weights.cwiseMax(0.0);
  for (int a = 0; a < 4; ++a)
    for (int b = a + 1; b < 4; ++b)
      if (w[a] > 0 && w[b] > 0 && joints[a] == joints[b]) {
        w[a] += w[b];
        w[b] = 0;
      }
  const double sum = w.sum();
  const bool had_weight = sum > 0;
  if (had_weight) w /= sum; else w = Eigen::Vector4d(1, 0, 0, 0);
  for (int c = 0; c < 4; ++c)
    if (w[c] == 0) joints[c] = 0;  // the validator warns about unused slots naming a joint
  weights = w;
  return had_weight;
}

}  // namespace mocapfill::gltf_internal
