// The weight ramp that blends, fades and thresholds use: 0 at 0, 1 at 1, flat at both ends,
// so a weight that follows it never kinks the motion it weighs.
#pragma once

#include <algorithm>

namespace mocapfill {

// 3x^2 - 2x^3 of x clamped to [0, 1].
inline double Smoothstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * (3.0 - 2.0 * x);
}

}  // namespace mocapfill
