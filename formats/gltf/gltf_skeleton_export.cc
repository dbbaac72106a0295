// The skin (and optional stick-figure mesh) written for a scene that has no skinned mesh of
// its own: glTF importers of Blender, Unity and Unreal build an armature or skeleton only
// from a skin, and Blender shows one only when a mesh is bound to it.
#include "formats/gltf/tinygltf_private.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "formats/gltf/gltf_export_internal.h"

namespace mocapfill::gltf_internal {

namespace {

// Bones shorter than this (zero-length End Sites, joints on top of their parent) get no
// geometry: their triangles would have no area.
constexpr double kMinBoneLengthM = 1e-4;
// Half-width of a bone's octahedron, as a share of its length, and its cap: thin enough to
// read as a skeleton, and a 1 m bone is not drawn as a slab.
constexpr double kBoneWidthShare = 0.08;
constexpr double kMaxBoneHalfWidthM = 0.02;
// Where along the bone the octahedron is widest (as Blender draws bones).
constexpr double kWidestAt = 0.2;

Eigen::Affine3d LocalRest(const Joint& joint) {
  return Eigen::Translation3d(joint.rest_translation) * joint.rest_rotation.normalized() *
         Eigen::Scaling(joint.rest_scale);
}

// World rest transforms; parents come before children (Skeleton's order).
std::vector<Eigen::Affine3d> WorldRest(const Skeleton& skeleton) {
  std::vector<Eigen::Affine3d> world(skeleton.num_joints());
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const int p = skeleton.parent(j);
    world[j] = p == kNoParent ? LocalRest(skeleton.joint(j)) : world[p] * LocalRest(skeleton.joint(j));
  }
  return world;
}

// Two unit vectors perpendicular to `axis` (unit) and to each other.
void Perpendiculars(const Eigen::Vector3d& axis, Eigen::Vector3d& u, Eigen::Vector3d& v) {
  const Eigen::Vector3d helper = std::abs(axis.y()) < 0.9 ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitX();
  u = axis.cross(helper).normalized();
  v = axis.cross(u);
}

// An octahedron from `head` to `tail`, every vertex bound fully to skin slot `slot`.
void AddBone(const Eigen::Vector3d& head, const Eigen::Vector3d& tail, int slot, MeshPrimitive& p) {
  const Eigen::Vector3d along = tail - head;
  const double length = along.norm();
  if (!(length >= kMinBoneLengthM)) return;
  Eigen::Vector3d u, v;
  Perpendiculars(along / length, u, v);
  const double r = std::min(kBoneWidthShare * length, kMaxBoneHalfWidthM);
  const Eigen::Vector3d ring = head + kWidestAt * along;
  const uint32_t base = static_cast<uint32_t>(p.positions.size());
  const Eigen::Vector3d corners[6] = {head, ring + r * u, ring + r * v, ring - r * u, ring - r * v, tail};
  for (const Eigen::Vector3d& c : corners) {
    p.positions.push_back(c.cast<float>());
    p.joints.push_back({static_cast<std::uint16_t>(slot), 0, 0, 0});
    p.weights.push_back(Eigen::Vector4f(1, 0, 0, 0));
  }
  // Counter-clockwise seen from outside: the head and tail fans over the ring 1-2-3-4.
  for (uint32_t k = 0; k < 4; ++k) {
    const uint32_t a = base + 1 + k, b = base + 1 + (k + 1) % 4;
    p.indices.insert(p.indices.end(), {base, b, a, base + 5, a, b});
  }
}

}  // namespace

Skin RestPoseSkin(const Skeleton& skeleton) {
  Skin skin;
  skin.name = kGeneratedSkeletonName;
  for (const Eigen::Affine3d& world : WorldRest(skeleton)) {
    skin.joints.push_back(static_cast<int>(skin.joints.size()));
    skin.inverse_bind_matrices.push_back(world.inverse(Eigen::Affine).matrix());
  }
  return skin;
}

Mesh StickFigureMesh(const Skeleton& skeleton) {
  const std::vector<Eigen::Affine3d> world = WorldRest(skeleton);
  MeshPrimitive p;
  p.base_color = Eigen::Vector4f(0.8f, 0.8f, 0.8f, 1.0f);
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const int parent = skeleton.parent(j);
    if (parent != kNoParent) AddBone(world[parent].translation(), world[j].translation(), parent, p);
    const Joint& joint = skeleton.joint(j);
    if (joint.end_site) AddBone(world[j].translation(), world[j] * *joint.end_site, j, p);
  }
  Mesh mesh;
  mesh.name = kGeneratedSkeletonName;
  mesh.skin = 0;
  if (!p.positions.empty()) mesh.primitives.push_back(std::move(p));
  return mesh;
}

bool NeedsGeneratedSkeleton(const Scene& scene, GltfSkeleton option) {
  if (option == GltfSkeleton::kNodes) return false;
  return std::none_of(scene.meshes.begin(), scene.meshes.end(), [](const Mesh& m) { return m.skin >= 0; });
}

Result<GeneratedSkeleton> ExportGeneratedSkeleton(const Skeleton& skeleton, bool with_mesh, BufferWriter& buffer,
                                                  tinygltf::Model& model, std::vector<int>& scene_roots) {
  GeneratedSkeleton out;
  const Skin skin = RestPoseSkin(skeleton);
  ASSIGN_OR_RETURN(out.skin, ExportSkin(skin, skeleton, buffer, model));
  if (!with_mesh) return out;
  const Mesh mesh = StickFigureMesh(skeleton);
  if (mesh.primitives.empty()) return out;  // a single joint, or every bone of zero length
  ASSIGN_OR_RETURN(out.mesh_node, ExportMesh(mesh, {skin}, skeleton, buffer, model));
  model.nodes[out.mesh_node].skin = out.skin;
  out.mesh = model.nodes[out.mesh_node].mesh;
  scene_roots.push_back(out.mesh_node);
  return out;
}

}  // namespace mocapfill::gltf_internal
