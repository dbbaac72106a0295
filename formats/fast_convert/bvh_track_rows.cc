#include "formats/fast_convert/bvh_track_rows.h"

#include <algorithm>
#include <cstring>
#include <utility>

#include "formats/fast_convert/rows_in_parallel.h"

namespace mocapfill::fast_convert {

namespace {

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

// ParsePiece's sink for .glb tracks: each frame, composed into arrays of its own, is packed
// as WriteGlb packs it (PackRotations, PackTranslation after scaling to metres) while it is in
// cache; `chunk` gathers what the join and the ranges need.
class TrackSink {
 public:
  TrackSink(const TrackTarget& target, Chunk& chunk)
      : target_(target), chunk_(chunk), previous_(target.layout.joints), current_(target.layout.joints),
        translations_(target.layout.joints) {
    chunk.last_packed.assign(target.layout.joints, Eigen::Vector4d::Zero());
    chunk.ranges.resize(target.position_joints.size());
  }
  Eigen::Quaterniond* Rotations(int64_t) { return current_.data(); }
  const Eigen::Quaterniond* Previous(int64_t) { return previous_.data(); }
  Eigen::Vector3d* Translations(int64_t) { return translations_.data(); }
  void Composed(int64_t frame, bool first, const bvh::rows::RowScanner& scanner, const bvh::rows::FrameComposer& composer);
  std::vector<Eigen::Quaterniond> TakeLastRotations() { return std::move(previous_); }

 private:
  const TrackTarget& target_;
  Chunk& chunk_;
  std::vector<Eigen::Quaterniond> previous_, current_;
  std::vector<Eigen::Vector3d> translations_;
};

void TrackSink::Composed(int64_t frame, bool first, const bvh::rows::RowScanner& scanner,
                         const bvh::rows::FrameComposer& composer) {
  const ClipTrackLayout& layout = target_.layout;
  if (first) chunk_.first_rotation = current_;
  // A kept rotation is the one before, so it packs to the floats before (PackRotation of q
  // towards its own packed +-q gives that packed value again).
  float* rotation_floats = target_.tracks + layout.RotationTrack(0) + 4 * frame;
  const size_t track_stride = 4 * layout.frames;
  PackListedRotations(current_.data(), composer.composed().data(), composer.composed().size(),
                      chunk_.last_packed.data(), rotation_floats, track_stride);
  for (const uint32_t j : composer.kept())
    std::memcpy(rotation_floats + j * track_stride, rotation_floats + j * track_stride - 4, 4 * sizeof(float));
  for (size_t k = 0; k < target_.position_joints.size(); ++k) {
    float* packed = target_.tracks + layout.TranslationTrack(k) + 3 * frame;
    if (!first && target_.position_groups[k] >= 0 && scanner.Reused(target_.position_groups[k])) {
      std::memcpy(packed, packed - 3, 3 * sizeof(float));  // the same text: the same value, range unchanged
      continue;
    }
    const Eigen::Vector3d t = translations_[target_.position_joints[k]] * target_.metres_per_unit;
    PackTranslation(t, packed);
    PositionRange& range = chunk_.ranges[k];
    if (first) {
      range.first = range.min = range.max = t;
    } else {
      range.min = range.min.cwiseMin(t);
      range.max = range.max.cwiseMax(t);
    }
  }
  std::swap(previous_, current_);
}

// The rows of `piece` packed into its frames of the tracks (ParsePiece with a TrackSink).
Chunk PackChunk(const RowPiece& piece, const TrackTarget& target, int64_t frame_limit) {
  Chunk chunk;
  TrackSink sink(target, chunk);
  const PieceParse parse = ParsePiece(piece, frame_limit, *target.samplers, *target.groups, target.channels,
                                      /*every_translation=*/false, sink);
  chunk.rows = parse.rows;
  chunk.ok = parse.ok && parse.rows > 0;
  if (chunk.ok) chunk.last_rotation = sink.TakeLastRotations();
  return chunk;
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
  const int64_t frames = static_cast<int64_t>(target.layout.frames);
  if (threads == 1 || rows_text.size() < kParallelRowsMinBytes) {
    RowPiece whole;
    whole.begin = rows_text.data();
    whole.end = rows_text.data() + rows_text.size();
    Chunk all = PackChunk(whole, target, frames);
    ranges = std::move(all.ranges);
    return all.ok && all.rows == frames;
  }
  std::vector<RowPiece> pieces = SplitIntoPieces(rows_text);
  std::vector<Chunk> chunks(pieces.size());
  CountAndParseOnTwoThreads(pieces, [&](size_t i) {
    chunks[i] = PackChunk(pieces[i], target, std::min(frames, pieces[i].first_frame + pieces[i].rows));
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
