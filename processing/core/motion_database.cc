#include "processing/core/motion_database.h"

#include <cmath>
#include <string>

#include "processing/core/rotation.h"

namespace mocapfill {

namespace {

Status CheckMatrix(const Eigen::MatrixXf& m, Eigen::Index rows, Eigen::Index cols, const std::string& what) {
  if (m.rows() != rows || m.cols() != cols)
    return InvalidData(what + " is " + std::to_string(m.rows()) + " x " + std::to_string(m.cols()) + ", expected " +
                       std::to_string(rows) + " x " + std::to_string(cols));
  // One vectorised sum finds any NaN or infinity (they propagate); values are radians, metres
  // and m/s, so a float sum of millions of them stays far from overflow.
  if (!std::isfinite(m.sum())) return InvalidData(what + " contains a non-finite value");
  return OkStatus();
}

}  // namespace

Result<MotionDatabase> MotionDatabase::FromParts(Parts parts) {
  if (!std::isfinite(parts.rate_hz) || parts.rate_hz <= 0.0) return InvalidData("database rate is not positive");
  const int joints = parts.skeleton.num_joints();
  if (joints == 0) return InvalidData("database skeleton has no joints");
  if (static_cast<int>(parts.reference.joint_means.size()) != joints)
    return InvalidData("database has " + std::to_string(parts.reference.joint_means.size()) + " joint means for " +
                       std::to_string(joints) + " joints");
  for (const Eigen::Quaterniond& q : parts.reference.joint_means)
    if (!q.coeffs().allFinite() || std::abs(q.norm() - 1.0) > 1e-6) return InvalidData("database joint mean is not a unit quaternion");
  const int root = parts.reference.root_joint;
  if (root < -1 || root >= joints) return InvalidData("database root joint index is out of range");
  const int channels = 3 * joints + (root >= 0 ? kNumRootFeatures : 0);
  long frames = 0;
  for (size_t i = 0; i < parts.clips.size(); ++i) {
    const ClipRange& c = parts.clips[i];
    if (c.first_frame != frames || c.num_frames <= 0)
      return InvalidData("clip " + std::to_string(i) + " ('" + c.name + "') does not follow the previous clip");
    if (!std::isfinite(c.start_heading_rad) || !c.start_position_m.allFinite())
      return InvalidData("clip '" + c.name + "' has a non-finite start pose");
    frames += c.num_frames;
  }
  RETURN_IF_ERROR(CheckMatrix(parts.signals, frames, channels, "signal matrix"));
  for (int j : parts.translated_joints)
    if (j < 0 || j >= joints || j == root) return InvalidData("translated joint index " + std::to_string(j) + " is invalid");
  RETURN_IF_ERROR(CheckMatrix(parts.translations, frames, 3 * static_cast<Eigen::Index>(parts.translated_joints.size()),
                              "translation matrix"));
  for (size_t b = 0; b < parts.bands.size(); ++b) {
    if (parts.bands[b].band < 0 || (b > 0 && parts.bands[b].band <= parts.bands[b - 1].band))
      return InvalidData("stored bands are not in ascending order");
    RETURN_IF_ERROR(CheckMatrix(parts.bands[b].values, frames, channels, "band L" + std::to_string(parts.bands[b].band)));
  }
  const CorrelationTable& table = parts.correlation;
  if (!table.empty() && (table.num_channels != channels ||
                         table.entries.size() != static_cast<size_t>(channels) * static_cast<size_t>(channels)))
    return InvalidData("correlation table does not match the channel count " + std::to_string(channels));
  for (const CorrelationEntry& e : table.entries)
    if (!(e.max_abs >= 0.0f && e.max_abs <= 1.0f) || !(std::abs(e.value) <= 1.0f) ||
        std::abs(e.lag_frames) > table.max_lag_frames)
      return InvalidData("correlation table holds an out-of-range entry");
  return MotionDatabase(std::move(parts));
}

Eigen::Quaterniond MotionDatabase::LocalRotation(int joint, const Eigen::Vector3d& channels) const {
  return joint_means()[joint] * ExpMap(channels);
}

std::optional<int> MotionDatabase::FindClip(const std::string& name) const {
  for (int i = 0; i < num_clips(); ++i)
    if (parts_.clips[i].name == name) return i;
  return std::nullopt;
}

std::vector<FrameSegment> MotionDatabase::Segments() const {
  std::vector<FrameSegment> segments;
  segments.reserve(parts_.clips.size());
  for (const ClipRange& c : parts_.clips) segments.push_back({c.first_frame, c.num_frames});
  return segments;
}

int MotionDatabase::RootFeatureChannel(int feature) const {
  return root_joint() >= 0 ? 3 * num_joints() + feature : -1;
}

std::string MotionDatabase::ChannelName(int channel) const {
  if (channel < 3 * num_joints()) return skeleton().name(channel / 3) + "." + "xyz"[channel % 3];
  return RootFeatureName(channel - 3 * num_joints());
}

const StoredBand* MotionDatabase::FindBand(int k) const {
  for (const StoredBand& b : parts_.bands)
    if (b.band == k) return &b;
  return nullptr;
}

size_t MotionDatabase::MemoryBytes() const {
  size_t bytes = sizeof(float) * (parts_.signals.size() + parts_.translations.size());
  for (const StoredBand& b : parts_.bands) bytes += sizeof(float) * b.values.size();
  bytes += sizeof(CorrelationEntry) * parts_.correlation.entries.size();
  return bytes;
}

}  // namespace mocapfill
