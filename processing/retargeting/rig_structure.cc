#include "processing/retargeting/rig_structure.h"

#include <Eigen/Geometry>
#include <algorithm>

namespace mocapfill {

namespace {
using B = HumanoidBone;
}  // namespace

using rig_names::NameKind;
using rig_names::Side;

RigStructure::RigStructure(const Skeleton& skeleton)
    : skeleton_(skeleton),
      children_(skeleton.num_joints()),
      depth_(skeleton.num_joints(), 0),
      subtree_size_(skeleton.num_joints(), 1) {
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    names_.push_back(rig_names::ParseJointName(skeleton.name(j)));
    const int p = skeleton.parent(j);
    if (p != kNoParent) {
      children_[p].push_back(j);
      depth_[j] = depth_[p] + 1;
    }
  }
  for (int j = skeleton.num_joints() - 1; j >= 0; --j)  // parents come before children
    if (skeleton.parent(j) != kNoParent) subtree_size_[skeleton.parent(j)] += subtree_size_[j];
}

int RigStructure::NextDown(int j) const {
  int best = -1, best_twist = -1;
  for (int c : children_[j]) {
    const std::string& helper = names_[c].helper;
    if (helper.empty()) {
      if (best < 0 || subtree_size_[c] > subtree_size_[best]) best = c;
    } else if (helper == "twist helper") {
      if (best_twist < 0 || subtree_size_[c] > subtree_size_[best_twist]) best_twist = c;
    }
  }
  if (best >= 0) return best;
  return best_twist >= 0 ? NextDown(best_twist) : -1;
}

int RigStructure::PrevUp(int j) const {
  int p = skeleton_.parent(j);
  while (p != kNoParent && (names_[p].helper == "twist helper" || names_[p].helper == "hip offset helper"))
    p = skeleton_.parent(p);
  return p;
}

int RigStructure::BestByName(NameKind kind, Side side) const {
  int best = -1;
  for (int j = 0; j < skeleton_.num_joints(); ++j)
    if (names_[j].kind == kind && names_[j].side == side && (best < 0 || depth_[j] < depth_[best])) best = j;
  return best;
}

std::vector<int> RigStructure::AllByName(NameKind kind) const {
  std::vector<int> out;
  for (int j = 0; j < skeleton_.num_joints(); ++j)
    if (names_[j].kind == kind) out.push_back(j);
  return out;
}

bool RigStructure::IsAncestor(int ancestor, int j) const {
  for (int k = j; k != kNoParent; k = skeleton_.parent(k))
    if (k == ancestor) return true;
  return false;
}

int RigStructure::CommonAncestor(int a, int b) const {
  while (depth_[a] > depth_[b]) a = skeleton_.parent(a);  // one walk up, however deep the rig
  while (depth_[b] > depth_[a]) b = skeleton_.parent(b);
  while (a != b) {
    a = skeleton_.parent(a);
    b = skeleton_.parent(b);
    if (a == kNoParent || b == kNoParent) return -1;
  }
  return a;
}

std::vector<int> RigStructure::TorsoChain(int hips, int top) const {
  std::vector<int> chain;
  for (int k = top; k != hips && k != kNoParent; k = skeleton_.parent(k))
    if (!IsHelper(k)) chain.push_back(k);
  std::reverse(chain.begin(), chain.end());
  if (chain.size() > 1) {
    std::vector<int> without;
    for (int k : chain)
      if (!names_[k].lower_back) without.push_back(k);
    if (!without.empty()) chain = without;
  }
  return chain;
}

std::vector<int> RigStructure::NeckChain(int top, const std::vector<int>& hands) const {
  int head = -1;
  for (int j = 0; j < skeleton_.num_joints(); ++j)
    if (names_[j].kind == NameKind::kHead && names_[j].side == Side::kNone && j != top && IsAncestor(top, j) &&
        (head < 0 || depth_[j] < depth_[head]))
      head = j;
  std::vector<int> chain;
  if (head >= 0) {
    for (int k = head; k != top; k = skeleton_.parent(k))
      if (!IsHelper(k)) chain.push_back(k);
    std::reverse(chain.begin(), chain.end());
    return chain;
  }
  // No joint named head (Rigify's DEF-spine.004..006): follow the middle chain, the children
  // without a side and without helpers, to its end.
  for (int k = top;;) {
    int next = -1;
    for (int c : children_[k]) {
      const bool to_a_hand = std::any_of(hands.begin(), hands.end(), [&](int h) { return h >= 0 && IsAncestor(c, h); });
      if (names_[c].side == Side::kNone && !IsHelper(c) && !to_a_hand &&
          (next < 0 || subtree_size_[c] > subtree_size_[next]))
        next = c;
    }
    if (next < 0) break;
    chain.push_back(next);
    k = next;
  }
  return chain;
}

std::optional<Eigen::Matrix3d> RigStructure::BodyFrame(const RigMapping& m,
                                                       const std::vector<Eigen::Vector3d>& pose) const {
  const int hips = m.joint(B::kHips), head = m.joint(B::kHead);
  if (hips < 0 || head < 0) return std::nullopt;
  const Eigen::Vector3d trunk = pose[head] - pose[hips];
  if (trunk.norm() < 1e-6) return std::nullopt;
  Eigen::Vector3d up = Eigen::Vector3d::UnitY();
  if (trunk.normalized().y() < 0.5) up = trunk.normalized();  // not upright as imported: trust hips -> head
  Eigen::Vector3d forward = Eigen::Vector3d::Zero();
  double foot_length = 0;
  for (auto [foot, toes] : {std::pair{B::kLeftFoot, B::kLeftToes}, std::pair{B::kRightFoot, B::kRightToes}}) {
    if (m.joint(foot) < 0 || m.joint(toes) < 0) continue;
    const Eigen::Vector3d d = pose[m.joint(toes)] - pose[m.joint(foot)];
    forward += d;
    foot_length += d.norm();
  }
  forward -= forward.dot(up) * up;
  // Toes ahead of the ankles must be plain to see: at least a fifth of the foot's length
  // across the trunk axis (in Bandai's zero pose the feet lie along the trunk).
  if (foot_length <= 0 || forward.norm() < 0.2 * foot_length) return std::nullopt;
  forward.normalize();
  Eigen::Matrix3d frame;
  frame.col(0) = up.cross(forward).normalized();  // left = up x forward (Y x Z = X)
  frame.col(1) = up;
  frame.col(2) = forward;
  return frame;
}

}  // namespace mocapfill
