#include "processing/motion/key_stances.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "processing/core/median.h"

namespace mocapfill {

namespace {

using Eigen::Vector3d;

// The hips' horizontal velocity is taken over this much either side of a key: a step's sway
// and bob average out, a turn does not.
constexpr double kTravelHalfWindowS = 0.15;

Vector3d Horizontal(Vector3d v) {
  v.y() = 0.0;
  return v;
}

Vector3d TravelAt(const std::vector<Vector3d>& hips, const std::vector<double>& times, int k) {
  const int n = static_cast<int>(hips.size());
  int a = k, b = k;
  while (a > 0 && times[k] - times[a - 1] <= kTravelHalfWindowS) --a;
  while (b + 1 < n && times[b + 1] - times[k] <= kTravelHalfWindowS) ++b;
  if (b == a) return Vector3d::Zero();
  return Horizontal(hips[b] - hips[a]) / (times[b] - times[a]);
}

double MedianKeyGap(const std::vector<double>& times, const std::vector<bool>& pinned) {
  std::vector<double> gaps;
  for (int f = 0, previous = -1; f < static_cast<int>(pinned.size()); ++f) {
    if (!pinned[f]) continue;
    if (previous >= 0) gaps.push_back(times[f] - times[previous]);
    previous = f;
  }
  return gaps.empty() ? 0.0 : UpperMedian(std::move(gaps));
}

}  // namespace

std::vector<bool> StancesAroundKeys(const std::vector<Vector3d>& track, const std::vector<Vector3d>& hips,
                                    const std::vector<double>& times, const std::vector<bool>& pinned,
                                    const std::vector<bool>& standing, double floor, const KeyStanceOptions& options) {
  const int n = static_cast<int>(track.size());
  std::vector<bool> stance(n, false);
  if (options.ahead_share <= 0.0 && options.behind_share <= 0.0) return stance;
  if (MedianKeyGap(times, pinned) <= options.room_s) return stance;
  double reach = 0.0;
  for (int f = 0; f < n; ++f) reach = std::max(reach, (track[f] - hips[f]).norm());
  const double ahead = options.ahead_share * reach, behind = options.behind_share * reach;
  for (int k = 0; k < n; ++k) {
    if (!pinned[k] || !standing[k] || track[k].y() > floor + options.max_height_m) continue;
    const Vector3d travel = TravelAt(hips, times, k);
    if (travel.norm() < options.min_travel_m_per_s) continue;
    const Vector3d along = travel.normalized();
    // Where the keyed foot lies along the travel from the hips at frame f: it falls behind
    // them as they walk on over it.
    const auto lead = [&](int f) { return Horizontal(track[k] - hips[f]).dot(along); };
    if (lead(k) > ahead || lead(k) < -behind) continue;
    stance[k] = true;
    for (int dir : {1, -1}) {
      std::vector<int> run;
      int f = k + dir;
      for (; f >= 0 && f < n; f += dir) {
        if (dir > 0 ? lead(f) < -behind : lead(f) > ahead) break;
        const double moved = Horizontal(track[f] - track[k]).norm();
        const bool still = moved <= options.still_m_per_s * std::abs(times[f] - times[k]);
        if (pinned[f] && !still) break;
        run.push_back(f);
      }
      if (f >= 0 && f < n && pinned[f])  // the key has the foot elsewhere: let the hold fade out first
        while (!run.empty() && std::abs(times[f] - times[run.back()]) <= options.room_s) run.pop_back();
      for (int g : run) stance[g] = true;
    }
  }
  return stance;
}

}  // namespace mocapfill
