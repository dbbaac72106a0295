// A character and its animations: what a file holds once read (skeleton, clips, meshes and
// skins), and what a program builds to hand a sketch to Fill. Lengths are metres, Y is up,
// rotations are unit quaternions stored x, y, z, w (glTF's order).
#pragma once

#include <Eigen/Core>
#include <memory>
#include <string>
#include <vector>

#include "mocapfill/export.h"

namespace mocapfill::api {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// One animation of a scene's skeleton, sampled: frame f is at times_s[f].
struct Clip {
  std::string name;
  double rate_hz = 30.0;    // the rate the samples were made at (nominal when times are irregular)
  Eigen::VectorXd times_s;  // per frame, strictly increasing from 0
  RowMatrix rotations;      // frames x (4 * joints): each joint's local rotation, x y z w
  RowMatrix translations;   // frames x (3 * joints): each joint's local translation (m)
  // Per joint: the frames at which the source keyed its rotation / translation, ascending.
  // A sketch's keyed joints are those with keys; joints without keys are the ones to fill.
  // A fully sampled source (BVH) keys every joint at every frame.
  std::vector<std::vector<int>> rotation_keys;
  std::vector<std::vector<int>> translation_keys;
};

class SceneAccess;

class MOCAPFILL_API Scene {
 public:
  Scene();
  ~Scene();
  Scene(const Scene& other);
  Scene& operator=(const Scene& other);
  Scene(Scene&& other) noexcept;
  Scene& operator=(Scene&& other) noexcept;

  // A skeleton with no animation, for building a sketch in code: joint names (unique),
  // parents (-1 for a root; a parent comes before its children), and each joint's rest
  // local transform: translations joints x 3 (m), rotations joints x 4 (x y z w).
  // Throws Error (kUsage) naming the bad joint.
  static Scene FromSkeleton(const std::vector<std::string>& names, const std::vector<int>& parents,
                            const RowMatrix& rest_translations, const RowMatrix& rest_rotations);

  int joint_count() const;
  std::vector<std::string> joint_names() const;
  std::vector<int> joint_parents() const;
  RowMatrix rest_translations() const;  // joints x 3
  RowMatrix rest_rotations() const;     // joints x 4, x y z w

  int clip_count() const;
  Clip clip(int index) const;  // throws Error (kUsage) for an index out of range
  // Replaces clip `index`, or appends it when index == clip_count(). Checks sizes, finite
  // values, increasing times and keys within the frames; throws Error (kUsage) naming the
  // field. Rotations are normalised.
  void set_clip(int index, const Clip& clip);
  void clear_clips();

  int mesh_count() const;
  std::string source_format() const;  // "bvh", "glb", "fbx", ... ("" when built in code)
  std::vector<std::string> warnings() const;  // recoverable oddities found when reading it

 private:
  friend class SceneAccess;
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mocapfill::api
