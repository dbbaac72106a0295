// The skeleton: a forest of joints stored flat, every parent before its children,
// so forward kinematics is one loop. Lengths are in metres once imported.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "processing/core/status.h"

namespace mocapfill {

constexpr int kNoParent = -1;

// The most joints a skeleton read from a file may have. Character rigs have tens to a few
// thousand (fingers, face, twist helpers); beyond this a file is refused as not a rig rather
// than read into gigabytes.
constexpr int kMaxSkeletonJoints = 100'000;

struct Joint {
  std::string name;                // unique within a skeleton; preserved exactly (spaces, colons)
  int parent = kNoParent;          // index of the parent joint, always < own index
  Eigen::Vector3d rest_translation = Eigen::Vector3d::Zero();  // local offset from the parent (m)
  Eigen::Quaterniond rest_rotation = Eigen::Quaterniond::Identity();
  Eigen::Vector3d rest_scale = Eigen::Vector3d::Ones();

  // Layout of the source's BVH channels, kept so that BVH export round-trips: names as
  // written in the CHANNELS line ("Xposition", "Zrotation", ...). Empty for non-BVH input
  // and for joints that had no channels.
  std::vector<std::string> bvh_channels;
  // Offset of a BVH "End Site" child (m), kept as data rather than as a joint.
  std::optional<Eigen::Vector3d> end_site;
  // The BVH OFFSET as written (m), kept only when it differs from rest_translation: a joint
  // whose position channels hold one constant value over the clip takes that value as its
  // rest translation (so the rest pose matches the animation), and BVH export writes this
  // OFFSET back so the file round-trips. Scaled and rotated with rest_translation.
  std::optional<Eigen::Vector3d> bvh_offset;
};

class Skeleton {
 public:
  Skeleton() = default;

  // Checks the invariants: non-empty unique names, parent < index, finite unit rest rotations.
  // Importers call this on what they build; processing may assume it holds.
  static Result<Skeleton> Build(std::vector<Joint> joints);

  int num_joints() const { return static_cast<int>(joints_.size()); }
  const Joint& joint(int j) const { return joints_[j]; }
  Joint& mutable_joint(int j) { return joints_[j]; }
  const std::vector<Joint>& joints() const { return joints_; }
  int parent(int j) const { return joints_[j].parent; }
  const std::string& name(int j) const { return joints_[j].name; }

  // Index of the joint named `name`, or nullopt.
  std::optional<int> Find(std::string_view name) const;
  // Indices of the joints with no parent (several roots are allowed).
  std::vector<int> Roots() const;
  // Children of j in index order.
  std::vector<int> Children(int j) const;
  // Number of edges between joints a and b in the skeleton graph, or -1 if they are in different trees.
  int HierarchyDistance(int a, int b) const;

 private:
  explicit Skeleton(std::vector<Joint> joints) : joints_(std::move(joints)) {}
  std::vector<Joint> joints_;
};

// The joint named `name`, or an error of `code`: "<what>: no joint named 'X' (closest: 'A',
// 'B', 'C')", so that a misspelt name is answered with the names it was probably meant as.
Result<int> FindJointNamed(const Skeleton& skeleton, const std::string& name, const std::string& what,
                           ErrorCode code = ErrorCode::kInvalidArgument);

}  // namespace mocapfill
