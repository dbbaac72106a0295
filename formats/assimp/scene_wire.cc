#include "formats/assimp/scene_wire.h"

#include <cstdint>
#include <cstring>
#include <optional>
#include <type_traits>

namespace mocapfill {

namespace {

// The wire must carry every field: a type that grows fails here until the wire grows with it
// (sizes of the x86-64 glibc build, where the project's CI runs).
#if defined(__x86_64__) && defined(__GLIBCXX__)
static_assert(sizeof(Joint) == 208, "Joint changed: update scene_wire.cc");
static_assert(sizeof(JointKeys) == 144, "JointKeys changed: update scene_wire.cc");
static_assert(sizeof(MotionClip) == 168, "MotionClip changed: update scene_wire.cc");
static_assert(sizeof(MeshPrimitive) == 160, "MeshPrimitive changed: update scene_wire.cc");
static_assert(sizeof(Mesh) == 64, "Mesh changed: update scene_wire.cc");
static_assert(sizeof(Skin) == 80, "Skin changed: update scene_wire.cc");
static_assert(sizeof(SourceInfo) == 192, "SourceInfo changed: update scene_wire.cc");
static_assert(sizeof(Scene) == 312, "Scene changed: update scene_wire.cc");
#endif

class WireWriter {
 public:
  std::string bytes;

  template <typename T>
  void Pod(const T& v) {
    static_assert(std::is_arithmetic_v<T>);
    bytes.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void Str(const std::string& s) {
    Pod<uint64_t>(s.size());
    bytes.append(s);
  }
  // Eigen fixed-size values: their coefficients.
  template <typename E>
  void Coeffs(const E& e) {
    bytes.append(reinterpret_cast<const char*>(e.data()), sizeof(typename E::Scalar) * E::SizeAtCompileTime);
  }
  void Coeffs(const Eigen::Quaterniond& q) { Coeffs(q.coeffs()); }
  template <typename T, typename Put>
  void List(const std::vector<T>& v, Put put) {
    Pod<uint64_t>(v.size());
    for (const T& x : v) put(x);
  }
  template <typename T>
  void Pods(const std::vector<T>& v) {
    List(v, [&](const T& x) { Pod(x); });
  }
  template <typename T>
  void CoeffList(const std::vector<T>& v) {
    List(v, [&](const T& x) { Coeffs(x); });
  }
};

class WireReader {
 public:
  explicit WireReader(std::string_view bytes) : rest_(bytes) {}
  bool failed() const { return failed_; }
  bool done() const { return rest_.empty(); }

  template <typename T>
  T Pod() {
    static_assert(std::is_arithmetic_v<T>);
    T v{};
    Take(&v, sizeof(T));
    return v;
  }
  std::string Str() {
    const uint64_t n = Count(1);
    std::string s(rest_.substr(0, n));
    Skip(n);
    return s;
  }
  template <typename E>
  void Coeffs(E& e) {
    Take(e.data(), sizeof(typename E::Scalar) * E::SizeAtCompileTime);
  }
  void Coeffs(Eigen::Quaterniond& q) { Coeffs(q.coeffs()); }
  // A count of elements at least `min_bytes` each, no more than the bytes left can hold (so
  // that broken bytes cannot ask for a huge allocation).
  uint64_t Count(uint64_t min_bytes) {
    const uint64_t n = Pod<uint64_t>();
    if (failed_ || n > rest_.size() / min_bytes) {
      failed_ = true;
      return 0;
    }
    return n;
  }
  template <typename T, typename Get>
  void List(std::vector<T>& v, uint64_t min_bytes, Get get) {
    v.resize(Count(min_bytes));
    for (T& x : v) get(x);
  }
  template <typename T>
  void Pods(std::vector<T>& v) {
    List(v, sizeof(T), [&](T& x) { x = Pod<T>(); });
  }
  template <typename T>
  void CoeffList(std::vector<T>& v, uint64_t min_bytes) {
    List(v, min_bytes, [&](T& x) { Coeffs(x); });
  }

 private:
  void Take(void* out, size_t n) {
    if (failed_ || rest_.size() < n) {
      failed_ = true;
      return;
    }
    std::memcpy(out, rest_.data(), n);
    rest_.remove_prefix(n);
  }
  void Skip(size_t n) {
    if (rest_.size() < n) failed_ = true;
    else rest_.remove_prefix(n);
  }

  std::string_view rest_;
  bool failed_ = false;
};

void PutOptionalVector(WireWriter& w, const std::optional<Eigen::Vector3d>& v) {
  w.Pod<uint8_t>(v.has_value());
  if (v) w.Coeffs(*v);
}

std::optional<Eigen::Vector3d> GetOptionalVector(WireReader& r) {
  if (r.Pod<uint8_t>() == 0) return std::nullopt;
  Eigen::Vector3d v;
  r.Coeffs(v);
  return v;
}

void PutJoint(WireWriter& w, const Joint& j) {
  w.Str(j.name);
  w.Pod<int32_t>(j.parent);
  w.Coeffs(j.rest_translation);
  w.Coeffs(j.rest_rotation);
  w.Coeffs(j.rest_scale);
  w.List(j.bvh_channels, [&](const std::string& c) { w.Str(c); });
  PutOptionalVector(w, j.end_site);
  PutOptionalVector(w, j.bvh_offset);
}

void GetJoint(WireReader& r, Joint& j) {
  j.name = r.Str();
  j.parent = r.Pod<int32_t>();
  r.Coeffs(j.rest_translation);
  r.Coeffs(j.rest_rotation);
  r.Coeffs(j.rest_scale);
  r.List(j.bvh_channels, 8, [&](std::string& c) { c = r.Str(); });
  j.end_site = GetOptionalVector(r);
  j.bvh_offset = GetOptionalVector(r);
}

void PutKeys(WireWriter& w, const JointKeys& k) {
  w.Pods(k.rotation_frames);
  w.Pods(k.translation_frames);
  w.Pods(k.rotation_times_s);
  w.CoeffList(k.rotation_values);
  w.Pods(k.translation_times_s);
  w.CoeffList(k.translation_values);
}

void GetKeys(WireReader& r, JointKeys& k) {
  r.Pods(k.rotation_frames);
  r.Pods(k.translation_frames);
  r.Pods(k.rotation_times_s);
  r.CoeffList(k.rotation_values, 32);
  r.Pods(k.translation_times_s);
  r.CoeffList(k.translation_values, 24);
}

void PutClip(WireWriter& w, const MotionClip& c) {
  w.Str(c.name);
  w.Pod(c.sample_rate_hz);
  w.Pod<int32_t>(c.num_frames);
  w.Pod<int32_t>(c.num_joints);
  w.Pods(c.frame_times_s);
  w.CoeffList(c.rotations);
  w.CoeffList(c.translations);
  w.Pods(c.translation_animated);
  w.List(c.keys, [&](const JointKeys& k) { PutKeys(w, k); });
}

void GetClip(WireReader& r, MotionClip& c) {
  c.name = r.Str();
  c.sample_rate_hz = r.Pod<double>();
  c.num_frames = r.Pod<int32_t>();
  c.num_joints = r.Pod<int32_t>();
  r.Pods(c.frame_times_s);
  r.CoeffList(c.rotations, 32);
  r.CoeffList(c.translations, 24);
  r.Pods(c.translation_animated);
  r.List(c.keys, 48, [&](JointKeys& k) { GetKeys(r, k); });
}

void PutPrimitive(WireWriter& w, const MeshPrimitive& p) {
  w.CoeffList(p.positions);
  w.CoeffList(p.normals);
  w.CoeffList(p.texcoords);
  w.Pods(p.indices);
  w.List(p.joints, [&](const std::array<std::uint16_t, 4>& a) {
    for (std::uint16_t x : a) w.Pod(x);
  });
  w.CoeffList(p.weights);
  w.Coeffs(p.base_color);
}

void GetPrimitive(WireReader& r, MeshPrimitive& p) {
  r.CoeffList(p.positions, 12);
  r.CoeffList(p.normals, 12);
  r.CoeffList(p.texcoords, 8);
  r.Pods(p.indices);
  r.List(p.joints, 8, [&](std::array<std::uint16_t, 4>& a) {
    for (std::uint16_t& x : a) x = r.Pod<std::uint16_t>();
  });
  r.CoeffList(p.weights, 16);
  r.Coeffs(p.base_color);
}

void PutScene(WireWriter& w, const Scene& s) {
  w.List(s.skeleton.joints(), [&](const Joint& j) { PutJoint(w, j); });
  w.List(s.clips, [&](const MotionClip& c) { PutClip(w, c); });
  w.List(s.meshes, [&](const Mesh& m) {
    w.Str(m.name);
    w.List(m.primitives, [&](const MeshPrimitive& p) { PutPrimitive(w, p); });
    w.Pod<int32_t>(m.skin);
    w.Pod<int32_t>(m.attach_joint);
  });
  w.List(s.skins, [&](const Skin& k) {
    w.Str(k.name);
    w.List(k.joints, [&](int j) { w.Pod<int32_t>(j); });
    w.CoeffList(k.inverse_bind_matrices);
  });
  const SourceInfo& i = s.source;
  w.Str(i.format);
  w.Str(i.path);
  w.Pod(i.unit_scale_to_m);
  w.Str(i.unit_name);
  w.Pod<uint8_t>(i.unit_detected);
  w.Str(i.up_axis);
  w.Pod(i.source_frame_time_s);
  w.Str(i.source_frame_time_text);
  w.Pod<int32_t>(i.declared_frames);
  w.List(s.warnings, [&](const std::string& x) { w.Str(x); });
}

Result<Scene> GetScene(WireReader& r, const std::string& path) {
  std::vector<Joint> joints;
  r.List(joints, 64, [&](Joint& j) { GetJoint(r, j); });
  Scene s;
  r.List(s.clips, 64, [&](MotionClip& c) { GetClip(r, c); });
  r.List(s.meshes, 24, [&](Mesh& m) {
    m.name = r.Str();
    r.List(m.primitives, 64, [&](MeshPrimitive& p) { GetPrimitive(r, p); });
    m.skin = r.Pod<int32_t>();
    m.attach_joint = r.Pod<int32_t>();
  });
  r.List(s.skins, 24, [&](Skin& k) {
    k.name = r.Str();
    r.List(k.joints, 4, [&](int& j) { j = r.Pod<int32_t>(); });
    r.CoeffList(k.inverse_bind_matrices, 128);
  });
  SourceInfo& i = s.source;
  i.format = r.Str();
  i.path = r.Str();
  i.unit_scale_to_m = r.Pod<double>();
  i.unit_name = r.Str();
  i.unit_detected = r.Pod<uint8_t>() != 0;
  i.up_axis = r.Str();
  i.source_frame_time_s = r.Pod<double>();
  i.source_frame_time_text = r.Str();
  i.declared_frames = r.Pod<int32_t>();
  r.List(s.warnings, 8, [&](std::string& x) { x = r.Str(); });
  if (r.failed() || !r.done()) return InvalidData(path + ": the isolated reader's answer is cut short or malformed");
  if (!joints.empty()) {  // a scene of meshes alone has no skeleton
    Result<Skeleton> skeleton = Skeleton::Build(std::move(joints));
    if (!skeleton.ok()) return skeleton.status().WithContext(path);
    s.skeleton = std::move(skeleton).value();
  }
  for (const MotionClip& c : s.clips) RETURN_IF_ERROR(c.Validate(s.skeleton).WithContext(path));
  return s;
}

}  // namespace

std::string EncodeSceneResult(const Result<Scene>& result) {
  WireWriter w;
  w.Pod<int32_t>(static_cast<int32_t>(result.status().code()));
  if (!result.ok()) {
    w.Str(result.status().message());
    return std::move(w.bytes);
  }
  PutScene(w, *result);
  return std::move(w.bytes);
}

Result<Scene> DecodeSceneResult(std::string_view bytes, const std::string& path) {
  WireReader r(bytes);
  const int32_t code = r.Pod<int32_t>();
  if (r.failed() || code < static_cast<int32_t>(ErrorCode::kOk) || code > static_cast<int32_t>(ErrorCode::kInternal))
    return InvalidData(path + ": the isolated reader's answer is cut short or malformed");
  if (code != static_cast<int32_t>(ErrorCode::kOk)) {
    std::string message = r.Str();
    if (r.failed() || !r.done()) return InvalidData(path + ": the isolated reader's answer is cut short or malformed");
    return Status(static_cast<ErrorCode>(code), std::move(message));
  }
  return GetScene(r, path);
}

}  // namespace mocapfill
