// Foot contacts found on a motion itself. A foot (or toe) joint on the ground stands near its
// lowest height and barely moves horizontally. Both cues are needed on filled motion: between
// keys the filled foot slides (which is what planting removes), so a speed threshold strict
// enough for capture misses most contacts, and height alone would also take a swing foot
// skimming the floor. The thresholds are therefore loose on speed and tight on height.
#pragma once

#include <vector>

#include <Eigen/Core>

namespace mocapfill {

struct ContactDetection {
  double max_height_m = 0.03;      // above the joint's floor
  double max_speed_m_per_s = 0.6;  // horizontal
  // With a body track: the speed limit rises to this share of the body's horizontal speed
  // (a fast body's stance foot, synthesised or textured, slides faster).
  double max_speed_share_of_body = 0.5;
  double max_gap_s = 0.14;         // two contacts this close (last to first frame) are one
  double min_duration_s = 0.09;    // shorter contacts (first to last frame) are dropped
};

// Per frame, whether the joint whose world positions are `track` (one per time of `times_s`,
// ascending) touches the ground, its floor being at height `floor_y` (metres, +Y up).
// `body` (optional): the hips' world positions at the same times.
std::vector<bool> DetectContacts(const std::vector<Eigen::Vector3d>& track, const std::vector<double>& times_s,
                                 double floor_y, const ContactDetection& options,
                                 const std::vector<Eigen::Vector3d>* body = nullptr);

// Joins contacts `max_gap_s` apart or closer and drops those shorter than `min_duration_s`
// (DetectContacts does this to its own; contacts found otherwise get the same clean-up).
void TidyContacts(const std::vector<double>& times_s, const ContactDetection& options, std::vector<bool>& contact);

// The median height (+Y) of the joint whose world positions are `track` over the frames `down`
// marks; -infinity where it marks none.
double StandingHeight(const std::vector<Eigen::Vector3d>& track, const std::vector<bool>& down);

// The height the joint stands at: StandingHeight, or its lowest height where `down` marks no
// frame (a foot the contacts never have stand, as in a short dash); -infinity for no frames.
double StandingOrLowestHeight(const std::vector<Eigen::Vector3d>& track, const std::vector<bool>& down);

// Maximal runs of true frames: [first, last] pairs, ascending.
std::vector<std::pair<int, int>> ContactRuns(const std::vector<bool>& contact);

}  // namespace mocapfill
