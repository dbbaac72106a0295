// What an importer produces and an exporter consumes: one skeleton, its clips, any
// skinned or rigid geometry that rides on it, and the provenance of the source
// (format, units, axes, frame timing) that exporters record and report.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"

namespace mocapfill {

// One drawable piece of a mesh. Positions in metres in the mesh's bind space.
struct MeshPrimitive {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> normals;                 // empty or one per position
  std::vector<Eigen::Vector2f> texcoords;               // empty or one per position
  std::vector<std::uint32_t> indices;                   // triangles; empty = non-indexed
  std::vector<std::array<std::uint16_t, 4>> joints;     // skin joint slots (indices into Skin::joints)
  std::vector<Eigen::Vector4f> weights;                 // one per position when skinned; sums to 1
  Eigen::Vector4f base_color = Eigen::Vector4f::Ones(); // linear RGBA, from the source material
};

struct Mesh {
  std::string name;
  std::vector<MeshPrimitive> primitives;
  int skin = -1;        // index into Scene::skins, or -1 for a rigid mesh
  int attach_joint = -1;  // rigid meshes: joint that carries it (-1 = scene root)
};

struct Skin {
  std::string name;
  std::vector<int> joints;                          // skeleton joint indices
  std::vector<Eigen::Matrix4d> inverse_bind_matrices;  // one per joint, metres
};

// Where the data came from and what was done to it on import. Exporters write this to
// glTF asset.extras so that a later import (or a user) can see and undo the conversion.
struct SourceInfo {
  std::string format;            // "bvh", "gltf", "glb", "fbx", ...
  std::string path;
  double unit_scale_to_m = 1.0;  // metres per source unit that was applied on import
  std::string unit_name = "m";   // "cm", "m", "in", "cmu", ... (how unit_scale_to_m was chosen)
  bool unit_detected = false;    // true when chosen from skeleton height rather than default/override
  std::string up_axis = "y";     // source up axis before conversion to Y-up
  double source_frame_time_s = 0.0;     // as read (BVH "Frame Time"), 0 when not applicable
  std::string source_frame_time_text;   // exact text, for reports
  int declared_frames = -1;             // BVH "Frames:" value, -1 when not applicable
};

struct Scene {
  Skeleton skeleton;
  std::vector<MotionClip> clips;
  std::vector<Mesh> meshes;
  std::vector<Skin> skins;
  SourceInfo source;
  std::vector<std::string> warnings;  // recoverable oddities found on import
};

}  // namespace mocapfill
