#include "formats/fast_convert/bvh_track_rows.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "formats/fast_convert/rows_in_parallel.h"

namespace mocapfill::fast_convert {

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
// (PackRotations, PackTranslation after scaling to metres).
Chunk PackChunk(const char* p, const char* end, const TrackTarget& target, int64_t first_frame, int64_t frame_limit) {
  const std::vector<JointSampler>& samplers = *target.samplers;
  const size_t joints = samplers.size();
  const ClipTrackLayout& layout = target.layout;
  std::vector<double> row(target.channels);
  bvh::rows::FrameComposer composer(samplers, *target.groups, /*every_translation=*/false);
  bvh::rows::RowScanner scanner(*target.groups, target.channels);
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
    if (frame >= frame_limit || scanner.Scan(p, end, row.data()).kind != RowEnd::kComplete)
      return chunk;
    const bool first = frame == first_frame;
    composer.Compose(scanner, row.data(), first ? nullptr : previous.data(), current.data(), translations.data());
    if (first) chunk.first_rotation = current;
    // A kept rotation is the one before, so it packs to the floats before (PackRotation of q
    // towards its own packed +-q gives that packed value again).
    float* rotation_floats = target.tracks + layout.RotationTrack(0) + 4 * frame;
    const size_t track_stride = 4 * layout.frames;
    PackListedRotations(current.data(), composer.composed().data(), composer.composed().size(), chunk.last_packed.data(),
                        rotation_floats, track_stride);
    for (const uint32_t j : composer.kept())
      std::memcpy(rotation_floats + j * track_stride, rotation_floats + j * track_stride - 4, 4 * sizeof(float));
    for (size_t k = 0; k < target.position_joints.size(); ++k) {
      float* packed = target.tracks + layout.TranslationTrack(k) + 3 * frame;
      if (!first && target.position_groups[k] >= 0 && scanner.Reused(target.position_groups[k])) {
        std::memcpy(packed, packed - 3, 3 * sizeof(float));  // the same text: the same value, range unchanged
        continue;
      }
      const Eigen::Vector3d t = translations[target.position_joints[k]] * target.metres_per_unit;
      PackTranslation(t, packed);
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

// Negates the joints of `after` whose rotation chains continue those of `before` in the
// other hemisphere (PieceMustBeNegated); `before` holds the chunk before's last values as
// they now stand, and on return `after`'s last values do too.
void JoinHemispheres(const TrackTarget& target, const Chunk& before, Chunk& after, int64_t first_frame,
                     int64_t end_frame) {
  const ClipTrackLayout& layout = target.layout;
  for (size_t j = 0; j < layout.joints; ++j) {
    if (!PieceMustBeNegated(after.first_rotation[j], before.last_rotation[j], &before.last_packed[j])) continue;
    float* track = target.tracks + layout.RotationTrack(j);
    for (int64_t i = 4 * first_frame; i < 4 * end_frame; ++i) track[i] = -track[i];
    after.last_rotation[j].coeffs() = -after.last_rotation[j].coeffs();
    after.last_packed[j] = -after.last_packed[j];
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
  if (threads == 1 || rows_text.size() < kParallelRowsMinBytes) {
    Chunk all = PackChunk(begin, end, target, 0, frames);
    ranges = std::move(all.ranges);
    return all.ok && all.rows == frames;
  }
  std::vector<RowPiece> pieces = SplitIntoPieces(rows_text);
  std::vector<Chunk> chunks(pieces.size());
  CountAndParseOnTwoThreads(pieces, [&](size_t i) {
    const RowPiece& piece = pieces[i];
    chunks[i] = PackChunk(piece.begin, piece.end, target, piece.first_frame, std::min(frames, piece.first_frame + piece.rows));
  });
  int64_t total = 0;
  for (size_t i = 0; i < pieces.size(); ++i) {
    if (!chunks[i].ok || chunks[i].rows != pieces[i].rows) return false;
    total += pieces[i].rows;
  }
  if (total != frames) return false;
  ranges = chunks[0].ranges;
  for (size_t i = 1; i < pieces.size(); ++i) {
    JoinHemispheres(target, chunks[i - 1], chunks[i], pieces[i].first_frame, pieces[i].first_frame + pieces[i].rows);
    MergeRanges(chunks[i].ranges, ranges);
  }
  return true;
}

}  // namespace mocapfill::fast_convert
