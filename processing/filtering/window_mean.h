// The mean of a signal over a window centred on each frame, the window clamped at the clip's
// ends (it holds fewer frames there rather than repeating the edge).
#pragma once

#include <Eigen/Core>

namespace mocapfill {

// Per frame t and column, the mean of rows max(0, t - half) .. min(rows - 1, t + half) of `m`.
Eigen::MatrixXd WindowMean(const Eigen::MatrixXd& m, int half);

}  // namespace mocapfill
