// Internal to the BVH readers: one motion row from text to local joint transforms, shared by
// the serial row loop (bvh_motion.cc, which reports every error with line:col) and the convert
// fast path's (formats/fast_convert: rows on two threads, rows straight into .glb tracks).
#pragma once

#include <Eigen/Geometry>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "formats/bvh/bvh_euler.h"
#include "formats/bvh/bvh_hierarchy.h"
#include "formats/bvh/bvh_number.h"
#include "processing/core/motion_clip.h"

namespace mocapfill::bvh::rows {

// Upper bound on frames x joints (processing/core/motion_clip.h): a tiny hierarchy with many
// joints but few channels cannot make a small file expand without limit.
inline constexpr size_t kMaxJointFrames = static_cast<size_t>(kMaxMotionJointFrames);

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
    const char* next = ParseFiniteNumber(p, end, row[c]);
    if (next == nullptr) return {RowEnd::kBadValue, c};
    p = next;
  }
  while (p < end && (*p == ' ' || *p == '\t')) ++p;
  if (p < end && *p != '\n' && *p != '\r') return {RowEnd::kLong, channels};
  return {RowEnd::kComplete, channels};
}

// Consecutive channels of one joint and one kind (positions or rotations): the runs a
// row's text repeats from one frame to the next when a joint holds still.
struct ChannelGroup {
  int first = 0;
  int count = 0;
};
std::vector<ChannelGroup> MakeChannelGroups(const ParsedHierarchy& hierarchy);

// ScanRow for row after row, reusing the values of a channel group whose text is byte for
// byte the text it had in the previous row (identical text, identical numbers): only what
// changed is parsed. Half of a Bandai-Namco row (21 joints' constant positions) and a fifth
// of a CMU one (joints that never turn) repeat. `row` must be the same array on every call,
// holding the previous row's values, and the previous row's text must still be in place (one
// buffer for the whole motion section). Results, errors and positions are ScanRow's.
class RowScanner {
 public:
  RowScanner(const std::vector<ChannelGroup>& groups, int channels)
      : groups_(groups), channels_(channels), previous_(groups.size()), reused_(groups.size(), 0) {}

  // Whether group g of the row just scanned repeated the previous row's text.
  bool Reused(size_t g) const { return reused_[g] != 0; }

  RowEnd Scan(const char*& p, const char* end, double* row) {
    for (size_t g = 0; g < groups_.size(); ++g) {
      const ChannelGroup& group = groups_[g];
      while (p < end && (*p == ' ' || *p == '\t')) ++p;
      if (p == end || *p == '\n' || *p == '\r') return {RowEnd::kShort, group.first};
      Text& previous = previous_[g];
      if (previous.length > 0 && static_cast<size_t>(end - p) > previous.length &&
          SameText(p, previous.begin, previous.length) && IsBvhSpace(p[previous.length])) {
        previous.begin = p;
        p += previous.length;
        reused_[g] = 1;
        continue;
      }
      reused_[g] = 0;
      const char* begin = p;
      for (int c = group.first; c < group.first + group.count; ++c) {
        if (c > group.first) {
          while (p < end && (*p == ' ' || *p == '\t')) ++p;
          if (p == end || *p == '\n' || *p == '\r') {
            previous.length = 0;
            return {RowEnd::kShort, c};
          }
        }
        const char* next = ParseFiniteNumber(p, end, row[c]);
        if (next == nullptr) {
          previous.length = 0;
          return {RowEnd::kBadValue, c};
        }
        p = next;
      }
      previous.begin = begin;
      previous.length = static_cast<size_t>(p - begin);
    }
    while (p < end && (*p == ' ' || *p == '\t')) ++p;
    if (p < end && *p != '\n' && *p != '\r') return {RowEnd::kLong, channels_};
    return {RowEnd::kComplete, channels_};
  }

 private:
  struct Text {
    const char* begin = nullptr;
    size_t length = 0;
  };

  // Whether a[0, n) == b[0, n), for a group's few dozen bytes: eight at a time, the last
  // eight overlapping the ones before (no byte loop, no call).
  static bool SameText(const char* a, const char* b, size_t n) {
    const auto load = [](const char* p) {
      uint64_t v;
      std::memcpy(&v, p, 8);
      return v;
    };
    if (n < 8) return std::memcmp(a, b, n) == 0;
    for (size_t i = 0; i + 8 < n; i += 8)
      if (load(a + i) != load(b + i)) return false;
    return load(a + n - 8) == load(b + n - 8);
  }

  const std::vector<ChannelGroup>& groups_;
  int channels_;
  std::vector<Text> previous_;
  std::vector<uint8_t> reused_;
};

// One frame's local transforms into rotations[j] / translations[j], j < samplers.size().
// Position channels replace the OFFSET component they name; rotation channels compose
// intrinsically in listed order (unlisted axes contribute nothing). Each rotation is
// flipped to the hemisphere of previous[j] (the same joint one frame earlier, nullptr for
// the first frame) here, while both are in cache, instead of in a strided pass afterwards.
// The sines and cosines of all of a row's half angles are taken in one vectorised call
// (SinCosDegreesBatch), which gives each joint's EulerComposer result bit for bit in a third
// of the time. One per thread: it keeps the row's angles between calls.
//
// A joint whose rotation text all repeats the previous row's (`scanner`, the RowScanner that
// read `row`, says so), or that has no rotation channels, is not composed again: its
// rotation is previous[j], which is what composing and the hemisphere flip would give bit for
// bit (the same angles give the same q, and q turned towards +-q is that +-q). CMU's joints
// that hold still are 15% of its rotations. Joints whose angles are all zero skip the
// trigonometry (they are the identity, as EulerComposer gives them).
class FrameComposer {
 public:
  // every_translation false: only joints with position channels get translations[j] (the
  // others' entries are left alone), for callers that read no other.
  FrameComposer(const std::vector<JointSampler>& samplers, const std::vector<ChannelGroup>& groups,
                bool every_translation = true);
  void Compose(const RowScanner& scanner, const double* row, const Eigen::Quaterniond* previous,
               Eigen::Quaterniond* rotations, Eigen::Vector3d* translations);

  // The joints of the last Compose whose rotation was composed (all of them when previous was
  // nullptr) and those that kept previous[j], each in increasing order.
  std::span<const uint32_t> composed() const { return {composed_.data(), composed_count_}; }
  std::span<const uint32_t> kept() const { return {kept_.data(), kept_count_}; }

 private:
  const std::vector<JointSampler>& samplers_;
  bool every_translation_;
  std::vector<uint32_t> position_joints_;  // joints with position channels
  // Joint j's rotation channels are in groups rotation_groups_[group_begin_[j], group_begin_[j + 1]).
  std::vector<uint32_t> rotation_groups_, group_begin_;
  std::vector<uint32_t> composed_, kept_, turning_;  // turning_: composed joints needing trigonometry
  size_t composed_count_ = 0, kept_count_ = 0;
  std::vector<double> half_angles_, sines_, cosines_;  // three per turning joint
};

}  // namespace mocapfill::bvh::rows
