// Stances around a sparsely keyed leg's keys. Keys sparser than a step (every 8 or 16 frames)
// catch a walking foot on the ground about once a step, and the slerp between them carries it
// on at the mean pace where the capture had it stand and then swing. A stance foot stays where
// it landed while the hips pass over it: it lands ahead of them along their travel and lifts
// behind them, at a distance that scales with the leg. So a foot on the ground at a key, where
// the fill's own contacts or the takes' vote have it standing, stands at the keyed place from
// when the hips were `ahead_share` of its reach short of it until they are `behind_share` past it.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace mocapfill {

struct KeyStanceOptions {
  // How far ahead of the hips along their travel the foot lands, and behind them it lifts, as
  // shares of the joint's reach (its largest distance from the hips over the clip); 0: off.
  double ahead_share = 0.2;
  double behind_share = 0.25;
  double min_travel_m_per_s = 0.3;  // slower hips are standing: their feet are held by other rules
  // A stance ends this long before a key that has the foot elsewhere, so the hold can fade out
  // (twice the planter's fade); keys this close or closer (median) carry the timing themselves.
  double room_s = 0.2;
  // A key inside the stance continues it only if the foot moved slower than this since the key
  // the stance began at (the rule of FootPlantOptions::key_still_m_per_s).
  double still_m_per_s = 0.05;
  double max_height_m = 0.03;  // above the floor: on the ground at the key
};

// Per frame, whether the joint whose world positions are `track` stands at a key of its leg.
// `hips`: the hips' positions; `pinned`: the leg's key frames; `standing`: where the fill's
// contacts or the takes' vote have the joint down; `floor`: its ground height (metres, +Y up).
std::vector<bool> StancesAroundKeys(const std::vector<Eigen::Vector3d>& track, const std::vector<Eigen::Vector3d>& hips,
                                    const std::vector<double>& times, const std::vector<bool>& pinned,
                                    const std::vector<bool>& standing, double floor, const KeyStanceOptions& options);

}  // namespace mocapfill
