#include "formats/bvh/bvh_motion_rows.h"

namespace mocapfill::bvh::rows {

FrameComposer::FrameComposer(const std::vector<JointSampler>& samplers) : samplers_(samplers) {
  size_t angles = 0;
  for (const JointSampler& s : samplers)
    if (s.num_rotations > 0) angles += 3;
  half_angles_.resize(angles);
  sines_.resize(angles);
  cosines_.resize(angles);
}

void FrameComposer::Compose(const double* row, const Eigen::Quaterniond* previous, Eigen::Quaterniond* rotations,
                            Eigen::Vector3d* translations) {
  size_t k = 0;
  for (const JointSampler& s : samplers_) {
    if (s.num_rotations == 0) continue;
    for (int i = 0; i < 3; ++i) half_angles_[k++] = s.rotation_index[i] >= 0 ? 0.5 * row[s.rotation_index[i]] : 0.0;
  }
  SinCosDegreesBatch(half_angles_.data(), k, sines_.data(), cosines_.data());
  k = 0;
  for (size_t j = 0; j < samplers_.size(); ++j) {
    const JointSampler& s = samplers_[j];
    Eigen::Vector3d t = s.offset;
    for (int a = 0; a < 3; ++a)
      if (s.position_index[a] >= 0) t[a] = row[s.position_index[a]];
    translations[j] = t;
    if (s.num_rotations == 0) {
      rotations[j] = Eigen::Quaterniond::Identity();
      continue;
    }
    // Joints that never turn (CMU's fingers, a fifth of its values) are exactly the
    // identity, as EulerComposer gives them (the trigonometry would give -0 for -0 angles).
    const auto angle = [&](int i) { return s.rotation_index[i] >= 0 ? row[s.rotation_index[i]] : 0.0; };
    Eigen::Quaterniond q = angle(0) == 0.0 && angle(1) == 0.0 && angle(2) == 0.0
                               ? Eigen::Quaterniond::Identity()
                               : s.compose(&sines_[k], &cosines_[k]);
    k += 3;
    if (previous != nullptr && q.coeffs().dot(previous[j].coeffs()) < 0.0) q.coeffs() = -q.coeffs();
    rotations[j] = q;
  }
}

}  // namespace mocapfill::bvh::rows
