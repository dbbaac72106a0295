// A swinging foot kept clear of the floor (processing/motion/foot_plant.cc applies it). Legs
// slerped between sparse keys under a linearly interpolated root, and legs blended from several
// takes, flatten the captured swing: a foot the capture has in the air skims the floor.
#pragma once

#include <vector>

namespace mocapfill {

struct SwingClearanceOptions {
  // A foot moving at `full_speed_m_per_s` or faster clears its floor by this; slower ones
  // (a rolling heel, a shuffle) proportionally less. 0: off.
  double clearance_m = 0.015;
  double full_speed_m_per_s = 2.0;
  // A keyed leg's keys this close together carry the swing themselves (no lift); this far
  // apart or more, not at all (full lift); in between, the lift grows with the gap.
  double dense_keys_s = 4.0 / 30;
  double sparse_keys_s = 8.0 / 30;
  // From each key the lift grows over this, so the leg meets the key's pose without a jolt.
  double key_ramp_s = 2.0 / 30;
  // Each frame's lift is the largest wanted within this either side, then smoothed (triangle)
  // over as much: the swing's lift rises and falls over several frames.
  double smooth_s = 2.0 / 30;
};

// Per frame, how far to raise the foot. `shortfall`: how far below the clearance it wants the
// foot is (<= 0 where it clears it); `free`: frames no key pins and no contact holds (the only
// ones lifted); `pinned`: the leg's key frames (none for a synthesised leg).
std::vector<double> SwingLift(const std::vector<double>& shortfall, const std::vector<bool>& free,
                              const std::vector<bool>& pinned, double frame_s, const SwingClearanceOptions& options);

}  // namespace mocapfill
