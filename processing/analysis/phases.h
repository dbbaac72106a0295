// Motion phases / fragmentation (thesis 4.2-4.3): a band-pass signal of one "master"
// channel is cut wherever its first derivative changes sign, so each fragment is one rising
// or falling half-swing (a walk cycle falls into four phases at the stride band).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/core/status.h"

namespace mocapfill {

struct PhaseOptions {
  // |d_t| below eps_fraction * std(signal) keeps the previous sign, so noise around a flat
  // stretch does not cut.
  double eps_fraction = 1e-3;
  // Fragments shorter than this are merged into their predecessor (or the next fragment
  // for the first one), seconds.
  double min_length_s = 0.1;

  Status Validate() const;
};

// One phase: frames [first, last] inclusive (consecutive fragments share their boundary
// frame: next.first == this.last), rising when the signal increases over it.
struct Phase {
  int first = 0;
  int last = 0;
  bool rising = false;
};

// Cuts `signal` (one channel sampled at rate_hz) into phases. d_t = x(t+1) - x(t); a cut is
// made at t where sign(d_t) != sign(d_(t-1)). A signal of fewer than 2 frames gives no phase;
// a monotone signal gives one. Errors: invalid options, non-finite samples (kInvalidArgument).
Result<std::vector<Phase>> FindPhases(const Eigen::VectorXd& signal, double rate_hz, const PhaseOptions& options = {});

}  // namespace mocapfill
