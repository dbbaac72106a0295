#include "formats/bvh_glb/bvh_track_rows.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <optional>
#include <system_error>
#include <thread>
#include <utility>

#include "formats/bvh/bvh_motion_parallel.h"
#include "formats/spread_thread.h"

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

// A chunk started its hemisphere chains afresh. Frame by frame, the serial parse would have
// turned its first rotation towards the chunk before's last one (sign1), and the packing
// its normalised value towards the last packed one (sign2); every later frame of the chunk
// follows, so the whole chunk differs from the serial result by sign1 * sign2 per joint
// (negation is exact, so every later decision only changes sign). `before` holds the chunk
// before's last values as they now stand; on return `after`'s last values do too.
void JoinHemispheres(const TrackTarget& target, const Chunk& before, Chunk& after, int64_t first_frame,
                     int64_t end_frame) {
  const ClipTrackLayout& layout = target.layout;
  for (size_t j = 0; j < layout.joints; ++j) {
    const Eigen::Quaterniond& q = after.first_rotation[j];
    const double sign1 = q.coeffs().dot(before.last_rotation[j].coeffs()) < 0.0 ? -1.0 : 1.0;
    const Eigen::Vector4d v = sign1 * Eigen::Vector4d(q.x(), q.y(), q.z(), q.w()).normalized();
    const double sign2 = v.dot(before.last_packed[j]) < 0 ? -1.0 : 1.0;
    if (sign1 * sign2 > 0.0) continue;
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

namespace {

// Rows are parsed in pieces of about this size, taken in turn by whichever thread is free:
// the two vCPUs of a shared machine run at different speeds from moment to moment, and
// halves finished up to 1.3 ms apart on a 6 ms CMU clip.
constexpr size_t kPieceBytes = size_t{64} << 10;

struct Piece {
  const char* begin = nullptr;
  const char* end = nullptr;
  int64_t first_frame = 0;
  int64_t rows = 0;
  Chunk chunk;
};

// Pieces of [begin, end) that start at line starts.
std::vector<Piece> SplitIntoPieces(const char* begin, const char* end) {
  const size_t bytes = static_cast<size_t>(end - begin);
  const size_t count = std::clamp<size_t>(bytes / kPieceBytes, 2, 256);
  std::vector<Piece> pieces;
  const char* start = begin;
  for (size_t i = 1; i <= count && start < end; ++i) {
    const char* stop = end;
    if (i < count) {
      const char* guess = begin + bytes * i / count;
      if (guess < start) guess = start;
      const void* line_break = std::memchr(guess, '\n', static_cast<size_t>(end - guess));
      if (line_break != nullptr) stop = static_cast<const char*>(line_break) + 1;
    }
    Piece piece;
    piece.begin = start;
    piece.end = stop;
    pieces.push_back(std::move(piece));
    start = stop;
  }
  return pieces;
}

// Runs `work` on this thread and on a helper thread (on another CPU, spread_thread.h)
// until `work` returns false on both; on this thread alone when no thread can be had.
template <class Work>
void OnBothThreads(Work work) {
  std::optional<SpreadThread> helper;
  try {
    helper.emplace([&] { while (work()) {} });
  } catch (const std::system_error&) {
  }
  while (work()) {}
  if (helper) helper->Join();
}

}  // namespace

bool PackRows(std::string_view rows_text, const TrackTarget& target, int threads, std::vector<PositionRange>& ranges) {
  const char* begin = rows_text.data();
  const char* end = begin + rows_text.size();
  const int64_t frames = static_cast<int64_t>(target.layout.frames);
  if (threads == 1 || rows_text.size() < bvh::kParallelMotionMinBytes) {
    Chunk all = PackChunk(begin, end, target, 0, frames);
    ranges = std::move(all.ranges);
    return all.ok && all.rows == frames;
  }
  // First every piece's rows are counted, so that each knows its first frame; then the
  // pieces are parsed. Both steps hand out pieces in order from one counter each.
  std::vector<Piece> pieces = SplitIntoPieces(begin, end);
  std::atomic<size_t> next_count{0}, next_parse{0}, counted{0};
  OnBothThreads(
      [&] {
        if (const size_t i = next_count++; i < pieces.size()) {
          pieces[i].rows = bvh::CountRows(pieces[i].begin, pieces[i].end);
          ++counted;
          return true;
        }
        while (counted.load() < pieces.size()) std::this_thread::yield();  // the other thread's last count
        const size_t i = next_parse++;
        if (i >= pieces.size()) return false;
        int64_t first_frame = 0;
        for (size_t k = 0; k < i; ++k) first_frame += pieces[k].rows;
        Piece& piece = pieces[i];
        piece.first_frame = first_frame;
        piece.chunk = PackChunk(piece.begin, piece.end, target, first_frame, std::min(frames, first_frame + piece.rows));
        return true;
      });
  int64_t total = 0;
  for (const Piece& piece : pieces) {
    if (!piece.chunk.ok || piece.chunk.rows != piece.rows) return false;
    total += piece.rows;
  }
  if (total != frames) return false;
  ranges = pieces[0].chunk.ranges;
  for (size_t i = 1; i < pieces.size(); ++i) {
    JoinHemispheres(target, pieces[i - 1].chunk, pieces[i].chunk, pieces[i].first_frame,
                    pieces[i].first_frame + pieces[i].rows);
    MergeRanges(pieces[i].chunk.ranges, ranges);
  }
  return true;
}

}  // namespace mocapfill::bvh_glb
