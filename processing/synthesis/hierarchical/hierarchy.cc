#include "processing/synthesis/hierarchical/hierarchy.h"

#include <algorithm>
#include <deque>
#include <limits>

namespace mocapfill {

namespace {

// Hierarchy distance of every joint to the nearest keyed joint (breadth-first over the tree).
std::vector<int> DistanceFromKeyed(const Skeleton& skeleton, const std::vector<std::uint8_t>& keyed) {
  const int n = skeleton.num_joints();
  std::vector<std::vector<int>> neighbours(n);
  for (int j = 0; j < n; ++j)
    if (skeleton.parent(j) != kNoParent) {
      neighbours[j].push_back(skeleton.parent(j));
      neighbours[skeleton.parent(j)].push_back(j);
    }
  std::vector<int> dist(n, std::numeric_limits<int>::max());
  std::deque<int> queue;
  for (int j = 0; j < n; ++j)
    if (keyed[j]) {
      dist[j] = 0;
      queue.push_back(j);
    }
  while (!queue.empty()) {
    const int j = queue.front();
    queue.pop_front();
    for (int k : neighbours[j])
      if (dist[k] > dist[j] + 1) {
        dist[k] = dist[j] + 1;
        queue.push_back(k);
      }
  }
  return dist;
}

}  // namespace

std::vector<int> JointChannels(const std::vector<int>& joints) {
  std::vector<int> channels;
  for (int j : joints)
    for (int a = 0; a < 3; ++a) channels.push_back(3 * j + a);
  return channels;
}

std::vector<JointGroup> PlanGroups(const Skeleton& skeleton, const std::vector<std::uint8_t>& joint_keyed) {
  const int n = skeleton.num_joints();
  const std::vector<int> dist = DistanceFromKeyed(skeleton, joint_keyed);
  std::vector<int> group_of(n, -1);
  std::vector<JointGroup> groups;
  for (int j = 0; j < n; ++j) {
    if (joint_keyed[j]) continue;
    const int p = skeleton.parent(j);
    if (p != kNoParent && group_of[p] >= 0 && skeleton.Children(p).size() == 1) {
      group_of[j] = group_of[p];
      groups[group_of[j]].joints.push_back(j);
      continue;
    }
    group_of[j] = static_cast<int>(groups.size());
    groups.push_back({"", {j}, dist[j] == std::numeric_limits<int>::max() ? n : dist[j]});
  }
  for (JointGroup& g : groups) {
    g.name = skeleton.name(g.joints.front());
    if (g.joints.size() > 1) g.name += ".." + skeleton.name(g.joints.back());
  }
  std::stable_sort(groups.begin(), groups.end(),
                   [](const JointGroup& a, const JointGroup& b) { return a.distance < b.distance; });
  return groups;
}

std::vector<DrivenChannel> ChooseDrivers(const MotionDatabase& db, const JointGroup& group,
                                         const std::vector<std::uint8_t>& joint_available,
                                         const std::vector<std::uint8_t>& joint_keyed, bool root_features_keyed,
                                         int max_joints, double synthesized_weight, double root_feature_weight,
                                         bool root_drives) {
  const CorrelationTable& table = db.correlation();
  const std::vector<int> targets = JointChannels(group.joints);
  struct Ranked {
    int joint;
    double score;
    double weight;
  };
  std::vector<Ranked> ranked;
  for (int j = 0; j < db.num_joints(); ++j) {
    if (!joint_available[j]) continue;
    double corr = 0.0;
    if (!table.empty())
      for (int a = 0; a < 3; ++a)
        for (int t : targets) corr = std::max(corr, double(table.at(3 * j + a, t).max_abs));
    const double weight = joint_keyed[j] ? 1.0 : synthesized_weight;
    if (weight > 0.0) ranked.push_back({j, corr * weight, weight});
  }
  // The keyed motion root (pelvis tilt) leads when asked: it carries the upper body.
  const int root = db.root_joint();
  if (root_drives && root >= 0 && joint_keyed[root])
    for (Ranked& r : ranked)
      if (r.joint == root) r.score = 2.0;
  std::stable_sort(ranked.begin(), ranked.end(), [](const Ranked& a, const Ranked& b) { return a.score > b.score; });
  if (max_joints > 0 && static_cast<int>(ranked.size()) > max_joints) ranked.resize(max_joints);
  std::vector<DrivenChannel> driven;
  for (const Ranked& r : ranked)
    for (int a = 0; a < 3; ++a) driven.push_back({3 * r.joint + a, r.weight});
  if (root_features_keyed && db.root_joint() >= 0 && root_feature_weight > 0.0)
    for (int f = 0; f < kNumRootFeatures; ++f) driven.push_back({db.RootFeatureChannel(f), root_feature_weight});
  return driven;
}

}  // namespace mocapfill
