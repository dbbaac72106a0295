#include "processing/retargeting/rig_limbs_by_pose.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <utility>

namespace mocapfill {

namespace {

// Proportions of a standing human, as fractions of its height, that decide what counts as a
// leg or an arm. Generous: children, stylised characters and A- or T-poses all pass; a tail,
// a prop or a sitting pose does not.
constexpr double kMinHipsHeight = 0.35;     // the hips stand this far above the lowest foot
constexpr double kMinLegSegment = 0.12;     // thigh and shin each drop at least this much
constexpr double kMaxFootMismatch = 0.15;   // both feet reach the same floor within this
constexpr double kMinArmReach = 0.6;       // hips to fingertip along the bones, in leg lengths
constexpr double kMaxSharedReach = 0.6;     // the arms part below this share of an arm's reach
constexpr double kMinArmSegment = 0.06;     // upper arm and forearm are each at least this long
constexpr double kMaxClavicleStart = 0.07;  // a clavicle starts this close to the chest's midline

Eigen::Vector3d Horizontal(Eigen::Vector3d v) {
  v.y() = 0;
  return v;
}

struct Chains {
  const RigStructure& rig;
  const std::vector<Eigen::Vector3d>& pose;
  std::vector<bool> leaf;      // a joint that is no helper and has no descendant that is none
  std::vector<int> lowest;     // the lowest leaf of each joint's subtree, or -1
  std::vector<int> branches;   // children that are no helper or lead to one that is none

  // One pass from the children up (parents come before children), so that a rig of many
  // joints costs time in proportion to its size.
  Chains(const RigStructure& r, const std::vector<Eigen::Vector3d>& p) : rig(r), pose(p) {
    const Skeleton& s = rig.skeleton();
    const int n = s.num_joints();
    std::vector<bool> below(n, false);  // has a non-helper descendant
    for (int j = n - 1; j >= 0; --j) {
      const int parent = s.parent(j);
      if (parent != kNoParent && (below[j] || !rig.IsHelper(j))) below[parent] = true;
    }
    leaf.resize(n);
    for (int j = 0; j < n; ++j) leaf[j] = !rig.IsHelper(j) && !below[j];
    // A zero-length leaf marks where a bone ends (Geno's LeftArmEnd beside the hand): no branch.
    branches.assign(n, 0);
    for (int j = 0; j < n; ++j) {
      const int parent = s.parent(j);
      if (parent != kNoParent && (below[j] || (leaf[j] && (pose[j] - pose[parent]).norm() > 1e-3)))
        ++branches[parent];
    }
    lowest.assign(n, -1);
    for (int j = n - 1; j >= 0; --j) {
      if (leaf[j]) lowest[j] = j;
      const int parent = s.parent(j);
      if (parent != kNoParent && lowest[j] >= 0 &&
          (lowest[parent] < 0 || pose[lowest[j]].y() < pose[lowest[parent]].y()))
        lowest[parent] = lowest[j];
    }
  }

  // The hand on an arm's path from the chest joint `top`: the first joint after two long
  // segments where the chain ends or splits into fingers; else the end of the longest two
  // segments past the clavicle, which starts near the midline (CMU's clavicle is as long as
  // its forearm, so lengths alone would take the elbow for the wrist).
  int HandOf(int top, const std::vector<int>& path, double height) const {
    for (size_t k = 2; k < path.size(); ++k) {
      if (k + 1 < path.size() && branches[path[k]] < 2) continue;
      if (Length(path[k - 2], path[k - 1]) >= kMinArmSegment * height &&
          Length(path[k - 1], path[k]) >= kMinArmSegment * height)
        return path[k];
      break;
    }
    const bool clavicle =
        path.size() >= 4 && Horizontal(pose[path[0]] - pose[top]).norm() < kMaxClavicleStart * height;
    const int i = LongestTwoSegments(path, clavicle ? 1 : 0);
    return i < 0 ? -1 : path[i + 2];
  }

  // Whether each joint lies in the subtree of `top`, in one pass.
  std::vector<bool> Subtree(int top) const {
    const Skeleton& s = rig.skeleton();
    std::vector<bool> in(s.num_joints(), false);
    for (int j = 0; j < s.num_joints(); ++j) in[j] = j == top || (s.parent(j) != kNoParent && in[s.parent(j)]);
    return in;
  }

  // The non-helper joints from just below `top` down to `end`.
  std::vector<int> Path(int top, int end) const {
    std::vector<int> path;
    for (int k = end; k != top && k != kNoParent; k = rig.skeleton().parent(k))
      if (!rig.IsHelper(k)) path.push_back(k);
    std::reverse(path.begin(), path.end());
    return path;
  }

  double Length(int a, int b) const { return (pose[b] - pose[a]).norm(); }

  // Index i of the two consecutive segments path[i] -> path[i+1] -> path[i+2] that are longest
  // together (thigh and shin, upper arm and forearm), or -1 for a path of fewer than 3 joints.
  int LongestTwoSegments(const std::vector<int>& path, size_t first = 0) const {
    int best = -1;
    double best_length = -1;
    for (size_t i = first; i + 2 < path.size(); ++i) {
      const double l = Length(path[i], path[i + 1]) + Length(path[i + 1], path[i + 2]);
      if (l > best_length) best_length = l, best = static_cast<int>(i);
    }
    return best;
  }
};



// The hips: walking up from the lowest foot, the first joint standing high enough above it
// with another branch that reaches the same floor. Fills the two legs' lowest leaves.
int FindHips(const Chains& c, double height, int feet[2]) {
  const Skeleton& s = c.rig.skeleton();
  std::vector<std::vector<int>> children(s.num_joints());
  for (int j = 0; j < s.num_joints(); ++j) {
    if (s.parent(j) != kNoParent) {
      children[s.parent(j)].push_back(j);
    } else {
      const int f = c.lowest[j];  // the lowest leaf of every tree
      if (f >= 0 && (feet[0] < 0 || c.pose[f].y() < c.pose[feet[0]].y())) feet[0] = f;
    }
  }
  if (feet[0] < 0) return -1;
  const double floor = c.pose[feet[0]].y();
  int on_path = feet[0];
  for (int a = s.parent(feet[0]); a != kNoParent; on_path = a, a = s.parent(a)) {
    if (c.pose[a].y() - floor < kMinHipsHeight * height) continue;
    for (int child : children[a]) {
      const int other = child == on_path ? -1 : c.lowest[child];
      if (other >= 0 && c.pose[other].y() - floor < kMaxFootMismatch * height) {
        feet[1] = other;
        return a;
      }
    }
  }
  return -1;
}

// The upper leg of the chain from the hips to `foot`, when thigh and shin both point down.
int UpperLeg(const Chains& c, int hips, int foot, double height) {
  const std::vector<int> path = c.Path(hips, foot);
  const int i = c.LongestTwoSegments(path);
  if (i < 0) return -1;
  const double thigh_drop = c.pose[path[i]].y() - c.pose[path[i + 1]].y();
  const double shin_drop = c.pose[path[i + 1]].y() - c.pose[path[i + 2]].y();
  if (thigh_drop < kMinLegSegment * height || shin_drop < kMinLegSegment * height) return -1;
  return path[i];
}

// Forward, from the ankles to the ends of the feet; zero when the feet show none.
Eigen::Vector3d Forward(const Chains& c, int hips, const int feet[2]) {
  Eigen::Vector3d forward = Eigen::Vector3d::Zero();
  for (int side = 0; side < 2; ++side) {
    const std::vector<int> path = c.Path(hips, feet[side]);
    const int i = c.LongestTwoSegments(path);
    if (i >= 0) forward += Horizontal(c.pose[feet[side]] - c.pose[path[i + 2]]);
  }
  return forward;
}

// The two hands: the two leaves reaching furthest along the bones from the hips (whatever the
// pose: arms hang, spread or point up), outside the legs and on different branches of the
// torso; each hand then sits where its chain ends in fingers (HandOf).
bool FindHands(const Chains& c, int hips, const int legs[2], int foot, double height, int hands[2]) {
  const Skeleton& s = c.rig.skeleton();
  const int n = s.num_joints();
  const std::vector<bool> body = c.Subtree(hips), leg_l = c.Subtree(legs[0]), leg_r = c.Subtree(legs[1]);
  std::vector<double> reach(n, 0.0);  // along the bones from the hips
  for (int j = 0; j < n; ++j)
    if (body[j] && j != hips) reach[j] = reach[s.parent(j)] + c.Length(s.parent(j), j);
  // An arm reaches at least this far: hips to fingertip is about one leg (CMU) to 1.5 (Geno).
  const double min_reach = kMinArmReach * reach[foot];
  const auto candidate = [&](int k) { return c.leaf[k] && body[k] && !leg_l[k] && !leg_r[k] && reach[k] >= min_reach; };
  int tips[2] = {-1, -1};
  for (int k = 0; k < n; ++k)
    if (candidate(k) && (tips[0] < 0 || reach[k] > reach[tips[0]])) tips[0] = k;
  if (tips[0] < 0) return false;
  // Where each joint leaves the first arm's path: the other arm leaves it at the chest, low on
  // the path; a finger of the same hand leaves it at the hand.
  std::vector<bool> on_path(n, false);
  for (int k = tips[0]; k != kNoParent; k = s.parent(k)) on_path[k] = true;
  std::vector<int> leaves_at(n, -1);
  for (int j = 0; j < n; ++j)
    leaves_at[j] = on_path[j] ? j : (s.parent(j) == kNoParent ? -1 : leaves_at[s.parent(j)]);
  for (int k = 0; k < n; ++k)
    if (candidate(k) && leaves_at[k] >= 0 && reach[leaves_at[k]] < kMaxSharedReach * reach[tips[0]] &&
        (tips[1] < 0 || reach[k] > reach[tips[1]]))
      tips[1] = k;
  if (tips[1] < 0) return false;
  const int top = leaves_at[tips[1]];
  if (top == hips || !body[top]) return false;
  for (int side = 0; side < 2; ++side) {
    const std::vector<int> path = c.Path(top, tips[side]);
    hands[side] = c.HandOf(top, path, height);
    if (hands[side] < 0) return false;
  }
  return true;
}

}  // namespace

std::optional<LimbsByPose> FindLimbsByPose(const RigStructure& rig, const std::vector<Eigen::Vector3d>& pose,
                                           std::string& why) {
  const Skeleton& s = rig.skeleton();
  if (pose.size() != static_cast<size_t>(s.num_joints()) || s.num_joints() < 7) {
    why = "no standing pose to look at";
    return std::nullopt;
  }
  double low = pose[0].y(), high = pose[0].y();
  for (const Eigen::Vector3d& p : pose) low = std::min(low, p.y()), high = std::max(high, p.y());
  const double height = high - low;
  const Chains c(rig, pose);
  LimbsByPose out;
  int feet[2] = {-1, -1};
  out.hips = height > 0 ? FindHips(c, height, feet) : -1;
  if (out.hips < 0) {
    why = "the rest pose shows no two chains hanging from one joint down to the floor (legs)";
    return std::nullopt;
  }
  for (int side = 0; side < 2; ++side) out.upper_leg[side] = UpperLeg(c, out.hips, feet[side], height);
  if (out.upper_leg[0] < 0 || out.upper_leg[1] < 0) {
    why = "the chains below '" + s.name(out.hips) + "' do not bend into a thigh and a shin";
    return std::nullopt;
  }
  int hands[2] = {-1, -1};
  if (FindHands(c, out.hips, out.upper_leg, feet[0], height, hands)) out.hand[0] = hands[0], out.hand[1] = hands[1];

  // Sides: left is up x forward (Y x Z = X for a rig facing +Z).
  const Eigen::Vector3d forward = Forward(c, out.hips, feet);
  if (forward.norm() > 1e-6) {
    out.sides_seen = true;
    const Eigen::Vector3d left = Eigen::Vector3d::UnitY().cross(forward.normalized());
    if ((pose[out.upper_leg[0]] - pose[out.upper_leg[1]]).dot(left) < 0) std::swap(out.upper_leg[0], out.upper_leg[1]);
    if (out.hand[0] >= 0 && (pose[out.hand[0]] - pose[out.hand[1]]).dot(left) < 0) std::swap(out.hand[0], out.hand[1]);
  }
  return out;
}

}  // namespace mocapfill
