// The hierarchy of a rig as the mapping walks it: parsed names, children, depths, and the
// walks along limbs that step over helpers (Rigify's twist halves sit between the thigh and
// the shin; Geno's zero-length UpLegEnd hangs beside the foot).
#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "processing/core/skeleton.h"
#include "processing/retargeting/rig_mapping.h"
#include "processing/retargeting/rig_names.h"

namespace mocapfill {

class RigStructure {
 public:
  explicit RigStructure(const Skeleton& skeleton);

  const Skeleton& skeleton() const { return skeleton_; }
  const rig_names::JointName& name(int j) const { return names_[j]; }
  bool IsHelper(int j) const { return !names_[j].helper.empty(); }

  // The next joint down a limb: the child that is no helper, carrying the largest subtree;
  // through a twist helper when that is the only way on. -1 at the end of the chain.
  int NextDown(int j) const;
  // The parent, stepping over twist and offset helpers. -1 above a root.
  int PrevUp(int j) const;

  // The joint of that name kind and side nearest the root (no helpers), or -1.
  int BestByName(rig_names::NameKind kind, rig_names::Side side) const;
  // Every joint of that name kind, any side (no helpers), for messages.
  std::vector<int> AllByName(rig_names::NameKind kind) const;

  bool IsAncestor(int ancestor, int j) const;  // true for ancestor == j
  int CommonAncestor(int a, int b) const;      // -1 when in different trees

  // Hips (excluded) up to top (included), without helpers; CMU's LowerBack is dropped when
  // other joints remain.
  std::vector<int> TorsoChain(int hips, int top) const;
  // From the top torso joint (excluded) up to the head (included): to the joint named "head"
  // when there is one above `top`, else along the middle chain: no side in its names, and
  // not leading to any of `hands`.
  std::vector<int> NeckChain(int top, const std::vector<int>& hands) const;

  // The body frame of a pose as columns (left, up, forward), when the pose shows it: up is
  // +Y when the head is above the hips, else hips to head; forward is from the ankles to the
  // toes, across up. nullopt for a degenerate pose (Bandai's zero pose: everything along +X).
  std::optional<Eigen::Matrix3d> BodyFrame(const RigMapping& mapping, const std::vector<Eigen::Vector3d>& pose) const;

 private:
  const Skeleton& skeleton_;
  std::vector<rig_names::JointName> names_;
  std::vector<std::vector<int>> children_;
  std::vector<int> depth_;
  std::vector<int> subtree_size_;
};

}  // namespace mocapfill
