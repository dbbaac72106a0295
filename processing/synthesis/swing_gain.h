// A blend swings less than the takes it averages. Each fragment's candidates are stretched onto
// it, yet their strides stay a little out of phase with each other, so their swings (an arm's,
// a thigh's) partly cancel in the average while the posture they share survives. The blend's
// swing about its own moving average is therefore scaled back up
// (FragmentFillOptions::swing_gain), leaving that average, the posture, where it was.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace mocapfill {

// The moving average the swing is measured about: this long on either side of each frame (a
// stride at a walk, so the swing averages out of it).
constexpr double kSwingHalfWindowS = 0.5;

// For each listed column of `out`: its mean over `half_window` frames on either side (fewer at
// the ends) plus `gain` times what departs from that mean.
void ScaleSwing(const std::vector<int>& channels, double gain, int half_window, Eigen::MatrixXd& out);

}  // namespace mocapfill
