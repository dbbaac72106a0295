#include "processing/analysis/phases.h"

#include <cmath>
#include <string>

namespace mocapfill {

namespace {

// Joins runs of phases that go the same way (left behind when a short blip was merged).
void JoinSameDirection(std::vector<Phase>& phases) {
  std::vector<Phase> joined;
  for (const Phase& p : phases) {
    if (!joined.empty() && joined.back().rising == p.rising) {
      joined.back().last = p.last;
    } else {
      joined.push_back(p);
    }
  }
  phases = std::move(joined);
}

void MergeShortPhases(std::vector<Phase>& phases, int min_frames) {
  while (phases.size() > 1) {
    size_t shortest = phases.size();
    for (size_t i = 0; i < phases.size(); ++i)
      if (phases[i].last - phases[i].first < min_frames &&
          (shortest == phases.size() || phases[i].last - phases[i].first < phases[shortest].last - phases[shortest].first))
        shortest = i;
    if (shortest == phases.size()) return;
    // The short phase is absorbed by its predecessor (its successor for the first phase);
    // the merged phase keeps the direction of the longer part.
    const size_t into = shortest == 0 ? 1 : shortest - 1;
    Phase& keep = phases[into];
    const Phase gone = phases[shortest];
    if (gone.last - gone.first > keep.last - keep.first) keep.rising = gone.rising;
    keep.first = std::min(keep.first, gone.first);
    keep.last = std::max(keep.last, gone.last);
    phases.erase(phases.begin() + static_cast<long>(shortest));
    JoinSameDirection(phases);
  }
}

}  // namespace

Status PhaseOptions::Validate() const {
  if (!std::isfinite(eps_fraction) || eps_fraction < 0.0) return InvalidArgument("phases: eps_fraction must be >= 0");
  if (!std::isfinite(min_length_s) || min_length_s < 0.0) return InvalidArgument("phases: min_length_s must be >= 0");
  return OkStatus();
}

Result<std::vector<Phase>> FindPhases(const Eigen::VectorXd& signal, double rate_hz, const PhaseOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0) return InvalidArgument("phases: rate_hz must be finite and > 0");
  if (!signal.allFinite()) return InvalidArgument("phases: the signal contains a non-finite sample");
  const int frames = static_cast<int>(signal.size());
  std::vector<Phase> phases;
  if (frames < 2) return phases;
  const double mean = signal.mean();
  const double std = std::sqrt((signal.array() - mean).square().mean());
  const double eps = options.eps_fraction * std;
  // Sign of each step; flat steps inherit the previous sign (or the first decided one).
  std::vector<int> sign(frames - 1, 0);
  int previous = 0;
  for (int t = 0; t + 1 < frames; ++t) {
    const double d = signal[t + 1] - signal[t];
    sign[t] = d > eps ? 1 : (d < -eps ? -1 : previous);
    previous = sign[t];
  }
  int first_decided = 0;
  for (int s : sign)
    if (s != 0) {
      first_decided = s;
      break;
    }
  for (int& s : sign) {
    if (s != 0) break;
    s = first_decided;
  }
  int start = 0;
  for (int t = 1; t + 1 < frames; ++t) {
    if (sign[t] != sign[t - 1]) {
      phases.push_back({start, t, sign[t - 1] > 0});
      start = t;
    }
  }
  phases.push_back({start, frames - 1, sign[frames - 2] > 0});
  MergeShortPhases(phases, static_cast<int>(std::ceil(options.min_length_s * rate_hz - 1e-9)));
  return phases;
}

}  // namespace mocapfill
