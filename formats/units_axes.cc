#include "formats/units_axes.h"

#include <cmath>
#include <limits>
#include <utility>

namespace mocapfill {

namespace {

const std::pair<const char*, double> kUnits[] = {
    {"m", 1.0}, {"cm", 0.01}, {"mm", 0.001}, {"in", 0.0254}, {"ft", 0.3048}, {"cmu", 0.056444},
};

constexpr double kPlausibleMinHeightM = 0.5;
constexpr double kPlausibleMaxHeightM = 3.0;
constexpr double kTypicalHeightM = 1.7;

}  // namespace

const std::vector<std::string>& UnitNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const auto& unit : kUnits) list.emplace_back(unit.first);
    return list;
  }();
  return names;
}

std::vector<std::string> UnitChoices() {
  std::vector<std::string> choices{"auto"};
  for (const std::string& name : UnitNames()) choices.push_back(name);
  return choices;
}

std::string UnitChoicesText() {
  std::string text;
  for (const std::string& choice : UnitChoices()) text += (text.empty() ? "" : ", ") + choice;
  return text;
}

std::optional<double> UnitScaleByName(const std::string& name) {
  for (const auto& [unit, scale] : kUnits)
    if (name == unit) return scale;
  return std::nullopt;
}

Result<UnitChoice> ResolveUnit(const std::string& requested, const std::string& default_name,
                               double height_in_units) {
  if (requested != "auto") {
    const auto scale = UnitScaleByName(requested);
    if (!scale) return InvalidArgument("unknown unit '" + requested + "' (expected auto, m, cm, mm, in, ft or cmu)");
    return UnitChoice{requested, *scale, false};
  }
  const double default_scale = *UnitScaleByName(default_name);
  const double height_m = height_in_units * default_scale;
  if (!(height_in_units > 0.0) || (height_m >= kPlausibleMinHeightM && height_m <= kPlausibleMaxHeightM))
    return UnitChoice{default_name, default_scale, false};
  UnitChoice best{default_name, default_scale, true};
  double best_error = std::numeric_limits<double>::infinity();
  for (const auto& [unit, scale] : kUnits) {
    const double error = std::abs(std::log(height_in_units * scale / kTypicalHeightM));
    if (error < best_error) {
      best_error = error;
      best = UnitChoice{unit, scale, true};
    }
  }
  return best;
}

void ScaleScene(Scene& scene, double scale) {
  if (scale == 1.0) return;
  for (int j = 0; j < scene.skeleton.num_joints(); ++j) {
    Joint& joint = scene.skeleton.mutable_joint(j);
    joint.rest_translation *= scale;
    if (joint.end_site) *joint.end_site *= scale;
    if (joint.bvh_offset) *joint.bvh_offset *= scale;
  }
  for (MotionClip& clip : scene.clips) {
    for (Eigen::Vector3d& t : clip.translations) t *= scale;
    for (JointKeys& keys : clip.keys)
      for (Eigen::Vector3d& t : keys.translation_values) t *= scale;
  }
  for (Mesh& mesh : scene.meshes)
    for (MeshPrimitive& prim : mesh.primitives)
      for (Eigen::Vector3f& p : prim.positions) p *= static_cast<float>(scale);
  for (Skin& skin : scene.skins)
    for (Eigen::Matrix4d& m : skin.inverse_bind_matrices) m.block<3, 1>(0, 3) *= scale;
}

void ConvertZUpToYUp(Scene& scene) {
  // Maps (x, y, z) Z-up to (x, z, -y) Y-up.
  const Eigen::Quaterniond c(Eigen::AngleAxisd(-0.5 * 3.14159265358979323846, Eigen::Vector3d::UnitX()));
  const Eigen::Matrix3d cm = c.toRotationMatrix();
  for (int j : scene.skeleton.Roots()) {
    Joint& joint = scene.skeleton.mutable_joint(j);
    joint.rest_translation = cm * joint.rest_translation;
    if (joint.bvh_offset) *joint.bvh_offset = cm * *joint.bvh_offset;
    joint.rest_rotation = (c * joint.rest_rotation).normalized();
    for (MotionClip& clip : scene.clips) {
      for (int f = 0; f < clip.num_frames; ++f) {
        clip.translation(f, j) = cm * clip.translation(f, j);
        clip.rotation(f, j) = (c * clip.rotation(f, j)).normalized();
      }
      if (static_cast<size_t>(j) < clip.keys.size()) {
        for (Eigen::Vector3d& t : clip.keys[j].translation_values) t = cm * t;
        for (Eigen::Quaterniond& q : clip.keys[j].rotation_values) q = (c * q).normalized();
      }
    }
  }
  for (MotionClip& clip : scene.clips) clip.MakeContinuous();
  // Skinned meshes live in bind space; world = joint_world * IBM * p, so rotating the
  // joints by C means the bind-space positions rotate by C and IBM' = C * IBM * C^-1.
  Eigen::Matrix4d c4 = Eigen::Matrix4d::Identity();
  c4.block<3, 3>(0, 0) = cm;
  for (Skin& skin : scene.skins)
    for (Eigen::Matrix4d& m : skin.inverse_bind_matrices) m = c4 * m * c4.transpose();
  for (Mesh& mesh : scene.meshes) {
    if (mesh.skin < 0 && mesh.attach_joint >= 0) continue;  // rides on a joint that was converted
    const Eigen::Matrix3f cf = cm.cast<float>();
    for (MeshPrimitive& prim : mesh.primitives) {
      for (Eigen::Vector3f& p : prim.positions) p = cf * p;
      for (Eigen::Vector3f& n : prim.normals) n = cf * n;
    }
  }
}

}  // namespace mocapfill
