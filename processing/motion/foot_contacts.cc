#include "processing/motion/foot_contacts.h"

#include <algorithm>
#include <cmath>

#include "processing/core/median.h"

namespace mocapfill {

namespace {

// Horizontal speed at frame f from its neighbours (one-sided at the ends), so that a foot
// arriving and one leaving both count as moving at the frame between.
double HorizontalSpeed(const std::vector<Eigen::Vector3d>& track, const std::vector<double>& times_s, int f) {
  const int n = static_cast<int>(track.size());
  const int a = std::max(0, f - 1), b = std::min(n - 1, f + 1);
  const double dt = times_s[b] - times_s[a];
  if (b == a || dt <= 0.0) return 0.0;
  const Eigen::Vector3d d = track[b] - track[a];
  return std::hypot(d.x(), d.z()) / dt;
}

}  // namespace

std::vector<bool> DetectContacts(const std::vector<Eigen::Vector3d>& track, const std::vector<double>& times_s,
                                 double floor_y, const ContactDetection& options,
                                 const std::vector<Eigen::Vector3d>* body) {
  std::vector<bool> contact(track.size(), false);
  const int n = static_cast<int>(track.size());
  for (int f = 0; f < n; ++f)
    contact[f] = track[f].y() <= floor_y + options.max_height_m &&
                 HorizontalSpeed(track, times_s, f) <=
                     std::max(options.max_speed_m_per_s,
                              body ? options.max_speed_share_of_body * HorizontalSpeed(*body, times_s, f) : 0.0);
  TidyContacts(times_s, options, contact);
  return contact;
}

void TidyContacts(const std::vector<double>& times_s, const ContactDetection& options, std::vector<bool>& contact) {
  // A contact flickering off for a frame or two is one contact; a blip of a frame or two is
  // none. Either would make the held foot jump from one anchor to another.
  std::vector<std::pair<int, int>> runs = ContactRuns(contact);
  for (size_t i = 0; i + 1 < runs.size(); ++i)
    if (times_s[runs[i + 1].first] - times_s[runs[i].second] <= options.max_gap_s + 1e-9)
      for (int f = runs[i].second + 1; f < runs[i + 1].first; ++f) contact[f] = true;
  for (const auto& [first, last] : ContactRuns(contact))
    if (times_s[last] - times_s[first] < options.min_duration_s)
      for (int f = first; f <= last; ++f) contact[f] = false;
}

std::vector<std::pair<int, int>> ContactRuns(const std::vector<bool>& contact) {
  std::vector<std::pair<int, int>> runs;
  const int n = static_cast<int>(contact.size());
  for (int f = 0; f < n; ++f) {
    if (!contact[f]) continue;
    int last = f;
    while (last + 1 < n && contact[last + 1]) ++last;
    runs.emplace_back(f, last);
    f = last;
  }
  return runs;
}

double StandingHeight(const std::vector<Eigen::Vector3d>& track, const std::vector<bool>& down) {
  std::vector<double> heights;
  for (size_t f = 0; f < track.size() && f < down.size(); ++f)
    if (down[f]) heights.push_back(track[f].y());
  if (heights.empty()) return -INFINITY;
  return UpperMedian(std::move(heights));
}

double StandingOrLowestHeight(const std::vector<Eigen::Vector3d>& track, const std::vector<bool>& down) {
  const double standing = StandingHeight(track, down);
  if (std::isfinite(standing)) return standing;
  if (track.empty()) return -INFINITY;
  double lowest = INFINITY;
  for (const Eigen::Vector3d& p : track) lowest = std::min(lowest, p.y());
  return lowest;
}

}  // namespace mocapfill
