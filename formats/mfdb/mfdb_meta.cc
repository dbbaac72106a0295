#include "formats/mfdb/mfdb_meta.h"

#include <nlohmann/json.hpp>

namespace mocapfill::mfdb {

namespace {

using Json = nlohmann::ordered_json;

Json Vec3(const Eigen::Vector3d& v) { return Json::array({v.x(), v.y(), v.z()}); }
Json Quat(const Eigen::Quaterniond& q) { return Json::array({q.w(), q.x(), q.y(), q.z()}); }

Eigen::Vector3d ToVec3(const Json& j) {
  if (!j.is_array() || j.size() != 3) throw std::runtime_error("expected 3 numbers");
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}
Eigen::Quaterniond ToQuat(const Json& j) {
  if (!j.is_array() || j.size() != 4) throw std::runtime_error("expected 4 numbers");
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>(), j.at(3).get<double>()};
}

Json EncodeJoint(const Joint& joint) {
  Json j;
  j["name"] = joint.name;
  j["parent"] = joint.parent;
  j["rest_translation_m"] = Vec3(joint.rest_translation);
  j["rest_rotation_wxyz"] = Quat(joint.rest_rotation);
  j["rest_scale"] = Vec3(joint.rest_scale);
  j["bvh_channels"] = joint.bvh_channels;
  if (joint.end_site) j["end_site_m"] = Vec3(*joint.end_site);
  if (joint.bvh_offset) j["bvh_offset_m"] = Vec3(*joint.bvh_offset);
  return j;
}

Joint DecodeJoint(const Json& j) {
  Joint joint;
  joint.name = j.at("name").get<std::string>();
  joint.parent = j.at("parent").get<int>();
  joint.rest_translation = ToVec3(j.at("rest_translation_m"));
  joint.rest_rotation = ToQuat(j.at("rest_rotation_wxyz"));
  joint.rest_scale = ToVec3(j.at("rest_scale"));
  joint.bvh_channels = j.at("bvh_channels").get<std::vector<std::string>>();
  if (j.contains("end_site_m")) joint.end_site = ToVec3(j.at("end_site_m"));
  if (j.contains("bvh_offset_m")) joint.bvh_offset = ToVec3(j.at("bvh_offset_m"));
  return joint;
}

}  // namespace

std::string EncodeMeta(const MotionDatabase::Parts& parts) {
  Json meta;
  meta["rate_hz"] = parts.rate_hz;
  meta["root_joint"] = parts.reference.root_joint;
  Json joints = Json::array();
  for (const Joint& joint : parts.skeleton.joints()) joints.push_back(EncodeJoint(joint));
  meta["skeleton"] = joints;
  Json means = Json::array();
  for (const Eigen::Quaterniond& q : parts.reference.joint_means) means.push_back(Quat(q));
  meta["joint_means_wxyz"] = means;
  Json clips = Json::array();
  for (const ClipRange& c : parts.clips) {
    clips.push_back({{"name", c.name},
                     {"labels", c.labels},
                     {"first_frame", c.first_frame},
                     {"num_frames", c.num_frames},
                     {"start_heading_rad", c.start_heading_rad},
                     {"start_position_m", Vec3(c.start_position_m)}});
  }
  meta["clips"] = clips;
  meta["frames"] = parts.signals.rows();
  meta["channels"] = parts.signals.cols();
  meta["translated_joints"] = parts.translated_joints;
  Json bands = Json::array();
  for (const StoredBand& b : parts.bands) bands.push_back({{"band", b.band}, {"peak_hz", b.peak_hz}});
  meta["bands"] = bands;
  meta["correlation"] = {{"num_channels", parts.correlation.num_channels},
                         {"max_lag_frames", parts.correlation.max_lag_frames},
                         {"band", parts.correlation.band},
                         {"rate_hz", parts.correlation.rate_hz},
                         {"entries", parts.correlation.entries.size()}};
  return meta.dump();
}

Result<Layout> DecodeMeta(std::string_view text, MotionDatabase::Parts& parts) {
  const Json meta = Json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (meta.is_discarded() || !meta.is_object()) return InvalidData("META section is not a JSON object");
  // nlohmann reports missing fields and wrong types by exception; they become one clear error.
  try {
    parts.rate_hz = meta.at("rate_hz").get<double>();
    std::vector<Joint> joints;
    for (const Json& j : meta.at("skeleton")) joints.push_back(DecodeJoint(j));
    Result<Skeleton> skeleton = Skeleton::Build(std::move(joints));
    if (!skeleton.ok()) return skeleton.status().WithContext("META skeleton");
    parts.skeleton = std::move(skeleton).value();
    parts.reference.root_joint = meta.at("root_joint").get<int>();
    parts.reference.joint_means.clear();
    for (const Json& q : meta.at("joint_means_wxyz")) parts.reference.joint_means.push_back(ToQuat(q));
    parts.clips.clear();
    for (const Json& c : meta.at("clips")) {
      ClipRange range;
      range.name = c.at("name").get<std::string>();
      range.labels = c.at("labels").get<ClipLabels>();
      range.first_frame = c.at("first_frame").get<int>();
      range.num_frames = c.at("num_frames").get<int>();
      range.start_heading_rad = c.at("start_heading_rad").get<double>();
      range.start_position_m = ToVec3(c.at("start_position_m"));
      parts.clips.push_back(std::move(range));
    }
    Layout layout;
    layout.frames = meta.at("frames").get<long>();
    layout.channels = meta.at("channels").get<int>();
    parts.translated_joints = meta.at("translated_joints").get<std::vector<int>>();
    layout.translation_columns = 3 * static_cast<int>(parts.translated_joints.size());
    parts.bands.clear();
    for (const Json& b : meta.at("bands")) {
      parts.bands.push_back({b.at("band").get<int>(), b.at("peak_hz").get<double>(), {}});
      layout.bands.push_back(parts.bands.back().band);
    }
    const Json& corr = meta.at("correlation");
    parts.correlation = {};
    parts.correlation.num_channels = corr.at("num_channels").get<int>();
    parts.correlation.max_lag_frames = corr.at("max_lag_frames").get<int>();
    parts.correlation.band = corr.at("band").get<int>();
    parts.correlation.rate_hz = corr.at("rate_hz").get<double>();
    const size_t entries = corr.at("entries").get<size_t>();
    layout.correlation_channels = entries == 0 ? 0 : parts.correlation.num_channels;
    if (layout.frames < 0 || layout.channels < 0 || parts.correlation.num_channels < 0 ||
        entries != static_cast<size_t>(layout.correlation_channels) * static_cast<size_t>(layout.correlation_channels))
      return InvalidData("META declares inconsistent matrix sizes");
    return layout;
  } catch (const std::exception& e) {
    return InvalidData(std::string("META section is malformed: ") + e.what());
  }
}

}  // namespace mocapfill::mfdb
