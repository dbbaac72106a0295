#include "processing/core/monotone_cubic.h"

#include <algorithm>

namespace mocapfill {

std::vector<double> MonotoneCubicThroughKeys(const std::vector<int>& frames, const std::vector<double>& values,
                                             int num_frames) {
  const int n = static_cast<int>(std::min(frames.size(), values.size()));
  std::vector<double> out(std::max(0, num_frames), n > 0 ? values[0] : 0.0);
  if (n < 2) return out;
  std::vector<double> secant(n - 1), tangent(n, 0.0);
  for (int i = 0; i + 1 < n; ++i) secant[i] = (values[i + 1] - values[i]) / (frames[i + 1] - frames[i]);
  for (int i = 1; i + 1 < n; ++i) {
    if (secant[i - 1] * secant[i] <= 0.0) continue;  // an extreme (or a flat side): flat
    // Weighted harmonic mean of the neighbouring secants (Fritsch and Butland's weights for
    // uneven spacing): never steeper than three times the smaller one, so no overshoot.
    const double before = frames[i] - frames[i - 1], after = frames[i + 1] - frames[i];
    const double w1 = 2.0 * after + before, w2 = after + 2.0 * before;
    tangent[i] = (w1 + w2) / (w1 / secant[i - 1] + w2 / secant[i]);
  }
  for (int i = 0; i + 1 < n; ++i) {
    const double h = frames[i + 1] - frames[i];
    for (int f = std::max(0, frames[i]); f <= frames[i + 1] && f < num_frames; ++f) {
      const double t = (f - frames[i]) / h, t2 = t * t, t3 = t2 * t;
      out[f] = (2 * t3 - 3 * t2 + 1) * values[i] + (t3 - 2 * t2 + t) * h * tangent[i] +
               (3 * t2 - 2 * t3) * values[i + 1] + (t3 - t2) * h * tangent[i + 1];
    }
  }
  for (int f = std::max(0, frames[n - 1] + 1); f < num_frames; ++f) out[f] = values[n - 1];
  return out;
}

}  // namespace mocapfill
