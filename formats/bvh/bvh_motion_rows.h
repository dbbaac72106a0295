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
  HalfAngleComposer compose = nullptr;
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
// The sines and cosines of all of a row's half angles are taken in one vectorised call
// (SinCosDegreesBatch), which gives each joint's EulerComposer result bit for bit in a third
// of the time. One per thread: it keeps the row's angles between calls.
class FrameComposer {
 public:
  explicit FrameComposer(const std::vector<JointSampler>& samplers);
  void Compose(const double* row, const Eigen::Quaterniond* previous, Eigen::Quaterniond* rotations,
               Eigen::Vector3d* translations);

 private:
  const std::vector<JointSampler>& samplers_;
  std::vector<double> half_angles_, sines_, cosines_;  // three per joint with rotation channels
};

}  // namespace mocapfill::bvh::rows
