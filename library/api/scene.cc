#include <algorithm>
#include <cmath>

#include "library/api/access.h"

namespace mocapfill::api {

namespace {

std::string JointField(const std::string& field, int joint) { return field + "[" + std::to_string(joint) + "]"; }

Clip ToPublic(const MotionClip& clip) {
  const int frames = clip.num_frames, joints = clip.num_joints;
  Clip out;
  out.name = clip.name;
  out.rate_hz = clip.sample_rate_hz;
  out.times_s.resize(frames);
  out.rotations.resize(frames, 4 * joints);
  out.translations.resize(frames, 3 * joints);
  for (int f = 0; f < frames; ++f) {
    out.times_s[f] = clip.time_s(f);
    for (int j = 0; j < joints; ++j) {
      const Eigen::Quaterniond& q = clip.rotation(f, j);
      out.rotations.block<1, 4>(f, 4 * j) << q.x(), q.y(), q.z(), q.w();
      out.translations.block<1, 3>(f, 3 * j) = clip.translation(f, j).transpose();
    }
  }
  out.rotation_keys.resize(joints);
  out.translation_keys.resize(joints);
  for (int j = 0; j < joints && j < static_cast<int>(clip.keys.size()); ++j) {
    out.rotation_keys[j] = clip.keys[j].rotation_frames;
    out.translation_keys[j] = clip.keys[j].translation_frames;
  }
  return out;
}

// Key frames of one joint: ascending, unique, within the clip.
Status CheckKeyFrames(const std::vector<int>& frames, int num_frames, const std::string& field) {
  for (size_t i = 0; i < frames.size(); ++i) {
    if (frames[i] < 0 || frames[i] >= num_frames)
      return InvalidArgument(field + ": key frame " + std::to_string(frames[i]) + " is outside the clip's " +
                             std::to_string(num_frames) + " frames");
    if (i > 0 && frames[i] <= frames[i - 1]) return InvalidArgument(field + ": key frames must be strictly ascending");
  }
  return OkStatus();
}

Result<MotionClip> FromPublic(const Clip& in, const Skeleton& skeleton) {
  const int joints = skeleton.num_joints();
  const int frames = static_cast<int>(in.times_s.size());
  if (frames == 0) return InvalidArgument("clip.times_s: a clip needs at least one frame");
  if (!(in.rate_hz > 0.0) || !std::isfinite(in.rate_hz)) return InvalidArgument("clip.rate_hz: must be positive");
  if (in.rotations.rows() != frames || in.rotations.cols() != 4 * joints)
    return InvalidArgument("clip.rotations: expected " + std::to_string(frames) + " x " + std::to_string(4 * joints) +
                           " (frames x 4 * joints), got " + std::to_string(in.rotations.rows()) + " x " +
                           std::to_string(in.rotations.cols()));
  const bool has_translations = in.translations.size() != 0;
  if (has_translations && (in.translations.rows() != frames || in.translations.cols() != 3 * joints))
    return InvalidArgument("clip.translations: expected " + std::to_string(frames) + " x " +
                           std::to_string(3 * joints) + " (frames x 3 * joints) or empty for the rest translations");
  MotionClip clip = MotionClip::RestPose(skeleton, frames, in.rate_hz);
  clip.name = in.name;
  bool uniform = true;
  for (int f = 0; f < frames; ++f)
    uniform = uniform && std::abs(in.times_s[f] - f / in.rate_hz) <= 1e-9 * std::max(1.0, in.times_s[f]);
  if (!uniform) clip.frame_times_s.assign(in.times_s.data(), in.times_s.data() + frames);
  for (int f = 0; f < frames; ++f) {
    for (int j = 0; j < joints; ++j) {
      const auto r = in.rotations.block<1, 4>(f, 4 * j);
      Eigen::Quaterniond q(r[3], r[0], r[1], r[2]);
      const double norm = q.norm();
      if (!std::isfinite(norm) || norm < 1e-6)
        return InvalidArgument("clip.rotations: frame " + std::to_string(f) + ", joint '" + skeleton.name(j) +
                               "' is not a rotation (zero or non-finite quaternion)");
      clip.rotation(f, j) = Eigen::Quaterniond(q.coeffs() / norm);
      if (has_translations) clip.translation(f, j) = in.translations.block<1, 3>(f, 3 * j).transpose();
    }
  }
  const auto keys_of = [&](const std::vector<std::vector<int>>& keys, const std::string& field) -> Status {
    if (!keys.empty() && static_cast<int>(keys.size()) != joints)
      return InvalidArgument(field + ": one list per joint expected (" + std::to_string(joints) + "), got " +
                             std::to_string(keys.size()));
    for (int j = 0; j < static_cast<int>(keys.size()); ++j)
      RETURN_IF_ERROR(CheckKeyFrames(keys[j], frames, JointField(field, j) + " ('" + skeleton.name(j) + "')"));
    return OkStatus();
  };
  RETURN_IF_ERROR(keys_of(in.rotation_keys, "clip.rotation_keys"));
  RETURN_IF_ERROR(keys_of(in.translation_keys, "clip.translation_keys"));
  for (int j = 0; j < joints; ++j) {
    if (j < static_cast<int>(in.rotation_keys.size())) clip.keys[j].rotation_frames = in.rotation_keys[j];
    if (j < static_cast<int>(in.translation_keys.size())) clip.keys[j].translation_frames = in.translation_keys[j];
  }
  clip.MakeContinuous();
  clip.DetectAnimatedTranslations();
  RETURN_IF_ERROR(clip.Validate(skeleton).WithContext("clip"));
  return clip;
}

}  // namespace

Scene SceneAccess::Wrap(mocapfill::Scene scene) {
  Scene out;
  out.impl_->scene = std::move(scene);
  return out;
}

void ThrowIfError(const Status& status, FailureStage stage) {
  if (status.ok()) return;
  throw Error(static_cast<ErrorKind>(FailureClass(status, stage)), status.message());
}

Scene::Scene() : impl_(std::make_unique<Impl>()) {}
Scene::~Scene() = default;
Scene::Scene(const Scene& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
Scene& Scene::operator=(const Scene& other) {
  if (this != &other) *impl_ = *other.impl_;
  return *this;
}
Scene::Scene(Scene&& other) noexcept : impl_(std::move(other.impl_)) { other.impl_ = std::make_unique<Impl>(); }
Scene& Scene::operator=(Scene&& other) noexcept {
  std::swap(impl_, other.impl_);
  return *this;
}

Scene Scene::FromSkeleton(const std::vector<std::string>& names, const std::vector<int>& parents,
                          const RowMatrix& rest_translations, const RowMatrix& rest_rotations) {
  const int joints = static_cast<int>(names.size());
  const auto fail = [](const std::string& message) { ThrowIfError(InvalidArgument(message), FailureStage::kInput); };
  if (joints == 0) fail("skeleton: no joints");
  if (static_cast<int>(parents.size()) != joints) fail("parents: one per joint expected");
  if (rest_translations.rows() != joints || rest_translations.cols() != 3)
    fail("rest_translations: expected joints x 3 (" + std::to_string(joints) + " x 3)");
  if (rest_rotations.rows() != joints || rest_rotations.cols() != 4)
    fail("rest_rotations: expected joints x 4 (" + std::to_string(joints) + " x 4, x y z w)");
  std::vector<Joint> list(joints);
  for (int j = 0; j < joints; ++j) {
    list[j].name = names[j];
    list[j].parent = parents[j];
    list[j].rest_translation = rest_translations.row(j).transpose();
    const auto r = rest_rotations.row(j);
    const Eigen::Quaterniond q(r[3], r[0], r[1], r[2]);
    if (!(q.norm() > 1e-6) || !std::isfinite(q.norm()))
      fail(JointField("rest_rotations", j) + " ('" + names[j] + "'): not a rotation");
    list[j].rest_rotation = q.normalized();
  }
  Result<Skeleton> skeleton = Skeleton::Build(std::move(list));
  ThrowIfError(skeleton.status().ok() ? skeleton.status() : InvalidArgument(skeleton.status().message()),
               FailureStage::kInput);
  mocapfill::Scene scene;
  scene.skeleton = std::move(skeleton).value();
  return SceneAccess::Wrap(std::move(scene));
}

int Scene::joint_count() const { return impl_->scene.skeleton.num_joints(); }

std::vector<std::string> Scene::joint_names() const {
  std::vector<std::string> names;
  for (const Joint& j : impl_->scene.skeleton.joints()) names.push_back(j.name);
  return names;
}

std::vector<int> Scene::joint_parents() const {
  std::vector<int> parents;
  for (const Joint& j : impl_->scene.skeleton.joints()) parents.push_back(j.parent);
  return parents;
}

RowMatrix Scene::rest_translations() const {
  const Skeleton& s = impl_->scene.skeleton;
  RowMatrix out(s.num_joints(), 3);
  for (int j = 0; j < s.num_joints(); ++j) out.row(j) = s.joint(j).rest_translation.transpose();
  return out;
}

RowMatrix Scene::rest_rotations() const {
  const Skeleton& s = impl_->scene.skeleton;
  RowMatrix out(s.num_joints(), 4);
  for (int j = 0; j < s.num_joints(); ++j) {
    const Eigen::Quaterniond& q = s.joint(j).rest_rotation;
    out.row(j) << q.x(), q.y(), q.z(), q.w();
  }
  return out;
}

int Scene::clip_count() const { return static_cast<int>(impl_->scene.clips.size()); }

Clip Scene::clip(int index) const {
  if (index < 0 || index >= clip_count())
    ThrowIfError(InvalidArgument("clip " + std::to_string(index) + ": the scene has " +
                                 std::to_string(clip_count()) + " clips"),
                 FailureStage::kInput);
  return ToPublic(impl_->scene.clips[index]);
}

void Scene::set_clip(int index, const Clip& clip) {
  if (index < 0 || index > clip_count())
    ThrowIfError(InvalidArgument("clip " + std::to_string(index) + ": the scene has " +
                                 std::to_string(clip_count()) + " clips (append at index " +
                                 std::to_string(clip_count()) + ")"),
                 FailureStage::kInput);
  Result<MotionClip> converted = FromPublic(clip, impl_->scene.skeleton);
  // Whatever is wrong with arrays handed in by the caller is a usage error.
  if (!converted.ok()) ThrowIfError(InvalidArgument(converted.status().message()), FailureStage::kInput);
  if (index == clip_count())
    impl_->scene.clips.push_back(std::move(converted).value());
  else
    impl_->scene.clips[index] = std::move(converted).value();
}

void Scene::clear_clips() { impl_->scene.clips.clear(); }

int Scene::mesh_count() const { return static_cast<int>(impl_->scene.meshes.size()); }
std::string Scene::source_format() const { return impl_->scene.source.format; }
std::vector<std::string> Scene::warnings() const { return impl_->scene.warnings; }

}  // namespace mocapfill::api
