#include "formats/bvh_glb/bvh_track_rows.h"

#include <algorithm>
#include <system_error>
#include <thread>
#include <utility>

#include "formats/bvh/bvh_motion_parallel.h"

namespace mocapfill::bvh_glb {

namespace {

using bvh::rows::JointSampler;
using bvh::rows::RowEnd;

constexpr double kAnimatedToleranceM = 1e-9;  // ReadBvh's (TranslationMoves)

// What the rest of the clip needs from a run of rows: for the hemisphere join, each joint's
// composed rotation at the first frame and its rotation and packed value at the last; the
// position ranges.
struct Chunk {
  bool ok = false;
  int64_t rows = 0;
  std::vector<Eigen::Quaterniond> first_rotation;
  std::vector<Eigen::Quaterniond> last_rotation;
  std::vector<Eigen::Vector4d> last_packed;
  std::vector<PositionRange> ranges;
};

// Parses the rows of [p, end) into frames first_frame, first_frame + 1, ... of the tracks,
// never at or past frame_limit. Each frame is composed as ReadBvh composes it (FrameComposer,
// hemisphere-matched to the frame before within the chunk) and packed as WriteGlb packs it
// (PackRotation, PackTranslation after scaling to metres).
Chunk PackChunk(const char* p, const char* end, const TrackTarget& target, int64_t first_frame, int64_t frame_limit) {
  const std::vector<JointSampler>& samplers = *target.samplers;
  const size_t joints = samplers.size();
  const ClipTrackLayout& layout = target.layout;
  std::vector<double> row(target.channels);
  bvh::rows::FrameComposer composer(samplers);
  std::vector<Eigen::Quaterniond> previous(joints), current(joints);
  std::vector<Eigen::Vector3d> translations(joints);
  Chunk chunk;
  chunk.last_packed.assign(joints, Eigen::Vector4d::Zero());
  chunk.ranges.resize(target.position_joints.size());
  for (int64_t frame = first_frame;; ++frame) {
    while (p < end && bvh::IsBvhSpace(*p)) ++p;
    if (p == end) {
      chunk.ok = chunk.rows > 0;
      chunk.last_rotation = std::move(previous);
      return chunk;
    }
    if (frame >= frame_limit || bvh::rows::ScanRow(p, end, row.data(), target.channels).kind != RowEnd::kComplete)
      return chunk;
    const bool first = frame == first_frame;
    composer.Compose(row.data(), first ? nullptr : previous.data(), current.data(), translations.data());
    if (first) chunk.first_rotation = current;
    for (size_t j = 0; j < joints; ++j)
      PackRotation(current[j], chunk.last_packed[j], target.tracks + layout.RotationTrack(j) + 4 * frame);
    for (size_t k = 0; k < target.position_joints.size(); ++k) {
      const Eigen::Vector3d t = translations[target.position_joints[k]] * target.metres_per_unit;
      PackTranslation(t, target.tracks + layout.TranslationTrack(k) + 3 * frame);
      PositionRange& range = chunk.ranges[k];
      if (first) {
        range.first = range.min = range.max = t;
      } else {
        range.min = range.min.cwiseMin(t);
        range.max = range.max.cwiseMax(t);
      }
    }
    std::swap(previous, current);
    ++chunk.rows;
  }
}

// The second chunk started its hemisphere chains afresh. Frame by frame, the serial parse
// would have turned its first rotation towards the first chunk's last one (sign1), and the
// packing its normalised value towards the last packed one (sign2); every later frame of the
// chunk follows, so the whole chunk differs from the serial result by sign1 * sign2 per
// joint (negation is exact, so every later decision only changes sign).
void JoinHemispheres(const TrackTarget& target, const Chunk& before, const Chunk& after, int64_t split_frame) {
  const ClipTrackLayout& layout = target.layout;
  for (size_t j = 0; j < layout.joints; ++j) {
    const Eigen::Quaterniond& q = after.first_rotation[j];
    const double sign1 = q.coeffs().dot(before.last_rotation[j].coeffs()) < 0.0 ? -1.0 : 1.0;
    const Eigen::Vector4d v = sign1 * Eigen::Vector4d(q.x(), q.y(), q.z(), q.w()).normalized();
    const double sign2 = v.dot(before.last_packed[j]) < 0 ? -1.0 : 1.0;
    if (sign1 * sign2 > 0.0) continue;
    float* track = target.tracks + layout.RotationTrack(j);
    for (size_t i = 4 * split_frame; i < 4 * layout.frames; ++i) track[i] = -track[i];
  }
}

void MergeRanges(const std::vector<PositionRange>& after, std::vector<PositionRange>& ranges) {
  for (size_t k = 0; k < ranges.size(); ++k) {
    ranges[k].min = ranges[k].min.cwiseMin(after[k].min);
    ranges[k].max = ranges[k].max.cwiseMax(after[k].max);
  }
}

}  // namespace

bool PositionRange::Moves() const {
  for (int c = 0; c < 3; ++c)
    if (max[c] - first[c] > kAnimatedToleranceM || first[c] - min[c] > kAnimatedToleranceM) return true;
  return false;
}

bool PackRows(std::string_view rows_text, const TrackTarget& target, int threads, std::vector<PositionRange>& ranges) {
  const char* begin = rows_text.data();
  const char* end = begin + rows_text.size();
  const int64_t frames = static_cast<int64_t>(target.layout.frames);
  std::optional<bvh::RowSplit> halves;
  if (threads != 1 && rows_text.size() >= bvh::kParallelMotionMinBytes) halves = bvh::SplitRowsInHalf(rows_text);
  if (!halves || halves->first_rows >= frames) {
    Chunk all = PackChunk(begin, end, target, 0, frames);
    ranges = std::move(all.ranges);
    return all.ok && all.rows == frames;
  }
  Chunk second;
  std::thread helper;
  try {
    helper = std::thread([&] { second = PackChunk(halves->split, end, target, halves->first_rows, frames); });
  } catch (const std::system_error&) {
    Chunk all = PackChunk(begin, end, target, 0, frames);  // no thread to be had
    ranges = std::move(all.ranges);
    return all.ok && all.rows == frames;
  }
  Chunk first = PackChunk(begin, halves->split, target, 0, halves->first_rows);
  helper.join();
  if (!first.ok || first.rows != halves->first_rows || !second.ok || first.rows + second.rows != frames) return false;
  JoinHemispheres(target, first, second, halves->first_rows);
  ranges = std::move(first.ranges);
  MergeRanges(second.ranges, ranges);
  return true;
}

}  // namespace mocapfill::bvh_glb
