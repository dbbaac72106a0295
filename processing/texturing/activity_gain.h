// How much of a take's captured detail a keyed channel takes: as much as the sketch moves that
// channel compared with the take, both seen through the same keys. Detail grows with motion
// (a vigorous wave trembles more than a timid one), so a still sketch textured from a livelier
// take took tremor its own motion would not have (texture_channels.h, ActivityMatch).
#pragma once

#include <Eigen/Core>

namespace mocapfill {

// Per frame and column, min(1, (a + floor_per_s) / (b + floor_per_s)), where a and b are the
// mean absolute speeds (units per second) of `sketch` and `source` over window_s around the
// frame (clamped at the clip's ends). `sketch` and `source` are frames x columns alike; the
// floor keeps stretches where both stand still at a gain near 1 rather than a ratio of noise.
Eigen::MatrixXd ActivityGain(const Eigen::MatrixXd& sketch, const Eigen::MatrixXd& source, double rate_hz,
                             double window_s, double floor_per_s);

}  // namespace mocapfill
