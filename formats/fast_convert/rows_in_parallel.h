// The MOTION rows of a large BVH file parsed on two threads, into a clip (ReadBvh's rows,
// through its MotionRowsParser hook) or into a .glb's float tracks (bvh_track_rows.h): one
// splitter and one hemisphere join for both. The text is cut into pieces at line starts,
// every piece's rows are counted so that each knows its first frame, and the pieces are
// parsed in turn by whichever thread is free. Each piece starts its quaternion hemisphere
// chains afresh; the join then negates whole pieces where the serial parse would have
// flipped, so the result is bit-identical to the serial loop's. Anything irregular makes
// the parser give up and the serial loop read the text again, reporting the exact error.
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string_view>
#include <vector>

#include "formats/bvh/bvh_motion_rows.h"
#include "processing/core/motion_clip.h"

namespace mocapfill::fast_convert {

// Motion text smaller than this is parsed on the calling thread: starting a thread costs
// more than it saves.
inline constexpr size_t kParallelRowsMinBytes = size_t{384} << 10;

// A run of whole lines of the motion section, parsed as one piece.
struct RowPiece {
  const char* begin = nullptr;
  const char* end = nullptr;
  int64_t first_frame = 0;  // rows of the pieces before
  int64_t rows = 0;         // rows counted in [begin, end)
};

// `rows_text` cut at line starts into pieces (at least two) of about 64 KiB: the two
// vCPUs of a shared machine run at different speeds from moment to moment, so small pieces
// taken in turn keep both busy to the end. Rows are not counted yet.
std::vector<RowPiece> SplitIntoPieces(std::string_view rows_text);

// Counts every piece's rows and sets its first frame, then calls parse(i) for every piece
// i, on this thread and on a helper thread started on another CPU (spread_thread.h), each
// taking the next piece in turn; on this thread alone when no thread can be had.
void CountAndParseOnTwoThreads(std::vector<RowPiece>& pieces, const std::function<void(size_t)>& parse);

// Whether a piece parsed to its end, and the rows it held.
struct PieceParse {
  bool ok = false;
  int64_t rows = 0;
};

// The fast path's row loop, for a clip and for .glb tracks alike: parses the rows of `piece`
// into frames piece.first_frame, piece.first_frame + 1, ..., never at or past frame_limit. Each
// row is scanned (RowScanner) and composed (FrameComposer) as ReadBvh composes it, into the
// arrays `sink` gives for its frame: sink.Rotations(frame), sink.Translations(frame) and
// sink.Previous(frame), the frame before's rotations (not asked for the piece's first frame,
// which is composed without one: the hemisphere join turns it). sink.Composed(frame, first,
// scanner, composer) then takes the frame.
template <class Sink>
PieceParse ParsePiece(const RowPiece& piece, int64_t frame_limit, const std::vector<bvh::rows::JointSampler>& samplers,
                      const std::vector<bvh::rows::ChannelGroup>& groups, int channels, bool every_translation,
                      Sink& sink) {
  std::vector<double> row(channels);
  bvh::rows::FrameComposer composer(samplers, groups, every_translation);
  bvh::rows::RowScanner scanner(groups, channels);
  PieceParse result;
  const char* p = piece.begin;
  for (int64_t frame = piece.first_frame;; ++frame) {
    while (p < piece.end && bvh::IsBvhSpace(*p)) ++p;
    if (p == piece.end) {
      result.ok = true;
      return result;
    }
    if (frame >= frame_limit || scanner.Scan(p, piece.end, row.data()).kind != bvh::rows::RowEnd::kComplete)
      return result;
    const bool first = frame == piece.first_frame;
    composer.Compose(scanner, row.data(), first ? nullptr : sink.Previous(frame), sink.Rotations(frame),
                     sink.Translations(frame));
    sink.Composed(frame, first, scanner, composer);
    ++result.rows;
  }
}

// The hemisphere join of one joint at a piece boundary. The serial parse would have turned
// the piece's first rotation `first` towards the rotation before it, `before_last` (sign 1),
// and a packed track would have turned its normalised value towards the last packed value
// `before_packed` (sign 2; nullptr for a clip, which is not packed). Every later frame of the
// piece follows its first, so the piece differs from the serial result by sign1 * sign2:
// true when the joint's rotations over the whole piece must be negated (negation is exact,
// so every later decision only changes sign).
bool PieceMustBeNegated(const Eigen::Quaterniond& first, const Eigen::Quaterniond& before_last,
                        const Eigen::Vector4d* before_packed);

// ReadBvh's MotionRowsParser: every row of `rows_text` (the text after the Frame Time line)
// into `clip` (rotations, translations, num_frames) on two threads. False, with the clip's
// arrays in an unspecified state, when the text is small or anything is irregular.
bool ParseRowsIntoClip(std::string_view rows_text, const std::vector<bvh::rows::JointSampler>& samplers,
                       const std::vector<bvh::rows::ChannelGroup>& groups, int channels, int64_t declared_frames,
                       MotionClip& clip);

}  // namespace mocapfill::fast_convert
