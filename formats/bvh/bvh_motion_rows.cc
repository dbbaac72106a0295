#include "formats/bvh/bvh_motion_rows.h"

namespace mocapfill::bvh::rows {

namespace {

// q, or -q when that is nearer the joint's rotation one frame earlier (none for a first frame).
Eigen::Quaterniond TowardsPrevious(Eigen::Quaterniond q, const Eigen::Quaterniond* previous, size_t j) {
  if (previous != nullptr && q.coeffs().dot(previous[j].coeffs()) < 0.0) q.coeffs() = -q.coeffs();
  return q;
}

}  // namespace

FrameComposer::FrameComposer(const std::vector<JointSampler>& samplers, const std::vector<ChannelGroup>& groups,
                             bool every_translation)
    : samplers_(samplers), every_translation_(every_translation) {
  // Channel -> joint for rotation channels, then each group to the joint whose rotation
  // channels it holds (a group is one joint's channels of one kind).
  std::vector<int> rotation_joint;
  size_t angles = 0;
  for (size_t j = 0; j < samplers.size(); ++j) {
    const JointSampler& s = samplers[j];
    if (s.num_rotations > 0) angles += 3;
    if (s.position_index[0] >= 0 || s.position_index[1] >= 0 || s.position_index[2] >= 0)
      position_joints_.push_back(static_cast<uint32_t>(j));
    for (int i = 0; i < 3; ++i) {
      const int c = s.rotation_index[i];
      if (c < 0) continue;
      if (static_cast<size_t>(c) >= rotation_joint.size()) rotation_joint.resize(static_cast<size_t>(c) + 1, -1);
      rotation_joint[static_cast<size_t>(c)] = static_cast<int>(j);
    }
  }
  std::vector<std::vector<uint32_t>> joint_groups(samplers.size());
  for (size_t g = 0; g < groups.size(); ++g) {
    const size_t first = static_cast<size_t>(groups[g].first);
    if (first < rotation_joint.size() && rotation_joint[first] >= 0)
      joint_groups[static_cast<size_t>(rotation_joint[first])].push_back(static_cast<uint32_t>(g));
  }
  for (const std::vector<uint32_t>& list : joint_groups) {
    group_begin_.push_back(static_cast<uint32_t>(rotation_groups_.size()));
    rotation_groups_.insert(rotation_groups_.end(), list.begin(), list.end());
  }
  group_begin_.push_back(static_cast<uint32_t>(rotation_groups_.size()));
  composed_.resize(samplers.size());
  kept_.resize(samplers.size());
  turning_.resize(samplers.size());
  half_angles_.resize(angles);
  sines_.resize(angles);
  cosines_.resize(angles);
}

void FrameComposer::Compose(const RowScanner& scanner, const double* row, const Eigen::Quaterniond* previous,
                            Eigen::Quaterniond* rotations, Eigen::Vector3d* translations) {
  const size_t joints = samplers_.size();
  if (every_translation_)
    for (size_t j = 0; j < joints; ++j) translations[j] = samplers_[j].offset;
  for (const uint32_t j : position_joints_) {
    const JointSampler& s = samplers_[j];
    translations[j] = s.offset;
    for (int a = 0; a < 3; ++a)
      if (s.position_index[a] >= 0) translations[j][a] = row[s.position_index[a]];
  }
  size_t composed = 0, kept = 0, turning = 0;
  for (size_t j = 0; j < joints; ++j) {
    if (previous != nullptr) {
      bool repeats = true;  // no rotation channels: the identity again
      for (uint32_t i = group_begin_[j]; i < group_begin_[j + 1]; ++i) repeats = repeats && scanner.Reused(rotation_groups_[i]);
      if (repeats) {
        kept_[kept++] = static_cast<uint32_t>(j);
        rotations[j] = previous[j];
        continue;
      }
    }
    composed_[composed++] = static_cast<uint32_t>(j);
    const JointSampler& s = samplers_[j];
    const auto angle = [&](int i) { return s.rotation_index[i] >= 0 ? row[s.rotation_index[i]] : 0.0; };
    const double a0 = angle(0), a1 = angle(1), a2 = angle(2);
    // Joints that never turn (CMU's fingers) are exactly the identity, as EulerComposer
    // gives them (the trigonometry would give -0 for -0 angles).
    if (a0 == 0.0 && a1 == 0.0 && a2 == 0.0) {
      rotations[j] = TowardsPrevious(Eigen::Quaterniond::Identity(), previous, j);
      continue;
    }
    double* half = &half_angles_[3 * turning];
    half[0] = 0.5 * a0;
    half[1] = 0.5 * a1;
    half[2] = 0.5 * a2;
    turning_[turning++] = static_cast<uint32_t>(j);
  }
  composed_count_ = composed;
  kept_count_ = kept;
  SinCosDegreesBatch(half_angles_.data(), 3 * turning, sines_.data(), cosines_.data());
  for (size_t i = 0; i < turning; ++i) {
    const size_t j = turning_[i];
    rotations[j] = TowardsPrevious(samplers_[j].compose(&sines_[3 * i], &cosines_[3 * i]), previous, j);
  }
}

}  // namespace mocapfill::bvh::rows
