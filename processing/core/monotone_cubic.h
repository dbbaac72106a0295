// A curve through keys that neither kinks nor overshoots: piecewise cubic Hermite with the
// Fritsch-Carlson tangents (PCHIP), the keyframe editors' "auto clamped" handles. A key
// between a rise and a fall (a local extreme) gets a flat tangent, so the curve never passes
// above or below its neighbouring keys.
#pragma once

#include <vector>

namespace mocapfill {

// The curve through (frames[i], values[i]) (frames strictly increasing) sampled at frames
// 0 .. num_frames - 1; constant before the first key and after the last. Fewer than two keys:
// the one value (or 0) everywhere.
std::vector<double> MonotoneCubicThroughKeys(const std::vector<int>& frames, const std::vector<double>& values,
                                             int num_frames);

}  // namespace mocapfill
