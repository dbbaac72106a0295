#include "processing/motion/swing_clearance.h"

#include <algorithm>
#include <cmath>

namespace mocapfill {

namespace {

// How much of the wanted lift a frame of a keyed leg gets: none next to keys close together,
// growing with the distance to the nearest key (so the lift meets each key's pose smoothly).
std::vector<double> KeyWeights(const std::vector<bool>& pinned, double frame_s, const SwingClearanceOptions& options) {
  const int n = static_cast<int>(pinned.size());
  std::vector<double> weights(n, 1.0);
  std::vector<int> previous(n, -1), next(n, -1);
  for (int f = 0, last = -1; f < n; ++f) previous[f] = last = pinned[f] ? f : last;
  for (int f = n - 1, last = -1; f >= 0; --f) next[f] = last = pinned[f] ? f : last;
  if (n == 0 || (previous[n - 1] < 0)) return weights;  // no keys: a synthesised leg
  const double span = std::max(1e-9, options.sparse_keys_s - options.dense_keys_s);
  for (int f = 0; f < n; ++f) {
    const int before = previous[f] < 0 ? n : f - previous[f], after = next[f] < 0 ? n : next[f] - f;
    const double gap_s = (previous[f] < 0 || next[f] < 0) ? INFINITY : (next[f] - previous[f]) * frame_s;
    const double to_key_s = std::min(before, after) * frame_s;
    // A gap of `dense_keys_s` up to rounding lifts nothing, not a rounding error's worth.
    const double by_gap = gap_s <= options.dense_keys_s + 1e-6
                              ? 0.0 : std::min(1.0, (gap_s - options.dense_keys_s) / span);
    weights[f] = by_gap * std::min(1.0, to_key_s / std::max(1e-9, options.key_ramp_s));
  }
  return weights;
}

}  // namespace

std::vector<double> SwingLift(const std::vector<double>& shortfall, const std::vector<bool>& free,
                              const std::vector<bool>& pinned, double frame_s, const SwingClearanceOptions& options) {
  const int n = static_cast<int>(shortfall.size());
  std::vector<double> lift(n, 0.0);
  if (options.clearance_m <= 0.0 || n == 0) return lift;
  const int half = std::max(1, static_cast<int>(std::lround(options.smooth_s / frame_s)));
  std::vector<double> widest(n, 0.0);
  for (int f = 0; f < n; ++f)
    for (int d = -half; d <= half; ++d)
      if (f + d >= 0 && f + d < n && free[f + d]) widest[f] = std::max(widest[f], shortfall[f + d]);
  const std::vector<double> weights = KeyWeights(pinned, frame_s, options);
  for (int f = 0; f < n; ++f) {
    if (!free[f]) continue;
    double sum = 0.0, total = 0.0;
    for (int d = -half; d <= half; ++d) {
      if (f + d < 0 || f + d >= n) continue;
      const double w = half + 1 - std::abs(d);
      sum += w * widest[f + d];
      total += w;
    }
    lift[f] = weights[f] * sum / total;
  }
  return lift;
}

}  // namespace mocapfill
