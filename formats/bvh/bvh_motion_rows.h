// Internal to formats/bvh: one motion row from text to local joint transforms, shared by
// the serial row loop (bvh_motion.cc, which reports every error with line:col) and the
// two-thread one for large files (bvh_motion_parallel.cc).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <vector>

#include "formats/bvh/bvh_euler.h"
#include "formats/bvh/bvh_hierarchy.h"
#include "formats/bvh/bvh_number.h"

namespace mocapfill::bvh::rows {

// Upper bound on frames x joints (about 6 GB of transforms): a tiny hierarchy with many
// joints but few channels could otherwise make a small file expand without limit.
inline constexpr size_t kMaxJointFrames = size_t{100'000'000};

// Where one joint's values sit in a motion row (absolute indices, -1 when absent).
struct JointSampler {
  std::array<int, 3> rotation_index{-1, -1, -1};
  std::array<int, 3> position_index{-1, -1, -1};
  int num_rotations = 0;
  EulerComposer compose = nullptr;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();
};

std::vector<JointSampler> MakeSamplers(const ParsedHierarchy& hierarchy);

struct RowEnd {
  enum Kind { kComplete, kShort, kBadValue, kLong } kind;
  int values;  // parsed before stopping
};

// Reads one row of `channels` values from p (which must start a non-blank line), leaving
// p at the line end, or where the row went wrong.
inline RowEnd ScanRow(const char*& p, const char* end, double* row, int channels) {
  for (int c = 0; c < channels; ++c) {
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    if (p == end || *p == '\n' || *p == '\r') return {RowEnd::kShort, c};
    const char* next = ParseNumber(p, end, row[c]);
    if (next == nullptr || !IsFiniteNumber(row[c])) return {RowEnd::kBadValue, c};
    p = next;
  }
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  if (p < end && *p != '\n' && *p != '\r') return {RowEnd::kLong, channels};
  return {RowEnd::kComplete, channels};
}

// One frame's local transforms into rotations[j] / translations[j], j < samplers.size().
// Position channels replace the OFFSET component they name; rotation channels compose
// intrinsically in listed order (unlisted axes contribute nothing). Each rotation is
// flipped to the hemisphere of previous[j] (the same joint one frame earlier, nullptr for
// the first frame) here, while both are in cache, instead of in a strided pass afterwards.
inline void ComposeFrame(const std::vector<JointSampler>& samplers, const double* row,
                         const Eigen::Quaterniond* previous, Eigen::Quaterniond* rotations,
                         Eigen::Vector3d* translations) {
  for (size_t j = 0; j < samplers.size(); ++j) {
    const JointSampler& s = samplers[j];
    Eigen::Vector3d t = s.offset;
    for (int a = 0; a < 3; ++a)
      if (s.position_index[a] >= 0) t[a] = row[s.position_index[a]];
    translations[j] = t;
    if (s.num_rotations == 0) {
      rotations[j] = Eigen::Quaterniond::Identity();
      continue;
    }
    std::array<double, 3> angles_deg{};
    for (int i = 0; i < 3; ++i)
      if (s.rotation_index[i] >= 0) angles_deg[i] = row[s.rotation_index[i]];
    Eigen::Quaterniond q = s.compose(angles_deg);
    if (previous != nullptr && q.coeffs().dot(previous[j].coeffs()) < 0.0) q.coeffs() = -q.coeffs();
    rotations[j] = q;
  }
}

}  // namespace mocapfill::bvh::rows
