// Re-pinning of keys after texturing: texturing moves a channel at its
// keys too; a motion displacement map takes the offsets back out, so every key holds exactly
// and the change fades smoothly in between.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace mocapfill {

// Subtracts from each listed channel c of `out` the cubic interpolation (Catmull-Rom through
// the keys, held beyond the first and the last) of its offsets from `keyed` at its key frames
// key_frames[c] (sorted; empty: the channel is left alone). `keyed` and `out` are frames x
// channels.
void RepinKeys(const Eigen::MatrixXd& keyed, const std::vector<std::vector<int>>& key_frames,
               const std::vector<int>& channels, Eigen::MatrixXd& out);

}  // namespace mocapfill
