#include "processing/core/skeleton.h"

#include "processing/core/closest_names.h"

#include <cmath>
#include <unordered_set>

namespace mocapfill {

Result<Skeleton> Skeleton::Build(std::vector<Joint> joints) {
  if (joints.empty()) return InvalidData("skeleton has no joints");
  std::unordered_set<std::string> names;
  for (int j = 0; j < static_cast<int>(joints.size()); ++j) {
    const Joint& joint = joints[j];
    if (joint.name.empty()) return InvalidData("joint " + std::to_string(j) + " has an empty name");
    if (!names.insert(joint.name).second) return InvalidData("duplicate joint name '" + joint.name + "'");
    if (joint.parent != kNoParent && (joint.parent < 0 || joint.parent >= j))
      return Internal("joint '" + joint.name + "' is stored before its parent");
    if (!joint.rest_translation.allFinite() || !joint.rest_rotation.coeffs().allFinite() ||
        !joint.rest_scale.allFinite())
      return InvalidData("joint '" + joint.name + "' has a non-finite rest transform");
    if (std::abs(joint.rest_rotation.norm() - 1.0) > 1e-6)
      return InvalidData("joint '" + joint.name + "' has a non-unit rest rotation");
  }
  return Skeleton(std::move(joints));
}

std::optional<int> Skeleton::Find(std::string_view name) const {
  for (int j = 0; j < num_joints(); ++j)
    if (joints_[j].name == name) return j;
  return std::nullopt;
}

std::vector<int> Skeleton::Roots() const {
  std::vector<int> roots;
  for (int j = 0; j < num_joints(); ++j)
    if (joints_[j].parent == kNoParent) roots.push_back(j);
  return roots;
}

std::vector<int> Skeleton::Children(int j) const {
  std::vector<int> children;
  for (int c = j + 1; c < num_joints(); ++c)
    if (joints_[c].parent == j) children.push_back(c);
  return children;
}

int Skeleton::HierarchyDistance(int a, int b) const {
  // Walk both joints up to their common ancestor; parents precede children, so the
  // deeper index always moves first.
  int steps = 0;
  while (a != b) {
    if (a > b) a = joints_[a].parent; else b = joints_[b].parent;
    if (a == kNoParent || b == kNoParent) return -1;
    ++steps;
  }
  return steps;
}

Result<int> FindJointNamed(const Skeleton& skeleton, const std::string& name, const std::string& what,
                           ErrorCode code) {
  if (const std::optional<int> joint = skeleton.Find(name)) return *joint;
  std::vector<std::string> names;
  for (const Joint& j : skeleton.joints()) names.push_back(j.name);
  return Status(code, what + ": no joint named '" + name + "' (closest: " + QuotedClosestNames(name, names) + ")");
}

}  // namespace mocapfill
