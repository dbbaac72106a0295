#include "formats/fast_convert/rows_in_parallel.h"

#include <algorithm>
#include <atomic>
#include <cstring>
#include <optional>
#include <system_error>
#include <thread>

#include "formats/fast_convert/large_buffer.h"
#include "formats/fast_convert/spread_thread.h"

namespace mocapfill::fast_convert {

namespace {

using bvh::rows::JointSampler;

constexpr size_t kPieceBytes = size_t{64} << 10;

// Runs `work` on this thread and on a helper thread until `work` returns false on both.
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

// ParsePiece's sink for a clip: every frame composed in place, into the clip's arrays, each
// piece's pages mapped by the thread about to fill them.
class ClipSink {
 public:
  ClipSink(MotionClip& clip, size_t joints, int64_t first_frame, int64_t frame_limit) : clip_(clip), joints_(joints) {
    const size_t first = static_cast<size_t>(first_frame) * joints;
    const size_t count = static_cast<size_t>(std::max<int64_t>(0, frame_limit - first_frame)) * joints;
    PrefaultForWrite(clip.rotations.data() + first, count * sizeof(Eigen::Quaterniond));
    PrefaultForWrite(clip.translations.data() + first, count * sizeof(Eigen::Vector3d));
  }
  Eigen::Quaterniond* Rotations(int64_t frame) { return clip_.rotations.data() + frame * joints_; }
  const Eigen::Quaterniond* Previous(int64_t frame) { return Rotations(frame) - joints_; }
  Eigen::Vector3d* Translations(int64_t frame) { return clip_.translations.data() + frame * joints_; }
  void Composed(int64_t, bool, const bvh::rows::RowScanner&, const bvh::rows::FrameComposer&) {}

 private:
  MotionClip& clip_;
  size_t joints_;
};

// Rows of [p, end): lines holding something other than blanks. Rows that end in a lone CR
// are undercounted; the parse then disagrees with the count and the serial loop takes over.
int64_t CountRows(const char* p, const char* end) {
  int64_t count = 0;
  while (true) {
    while (p < end && bvh::IsBvhSpace(*p)) ++p;
    if (p == end) return count;
    ++count;
    const void* line_break = std::memchr(p, '\n', static_cast<size_t>(end - p));
    p = line_break != nullptr ? static_cast<const char*>(line_break) + 1 : end;
  }
}

}  // namespace

std::vector<RowPiece> SplitIntoPieces(std::string_view rows_text) {
  const char* begin = rows_text.data();
  const char* end = begin + rows_text.size();
  const size_t bytes = rows_text.size();
  const size_t count = std::clamp<size_t>(bytes / kPieceBytes, 2, 256);
  std::vector<RowPiece> pieces;
  const char* start = begin;
  for (size_t i = 1; i <= count && start < end; ++i) {
    const char* stop = end;
    if (i < count) {
      const char* guess = std::max(begin + bytes * i / count, start);
      const void* line_break = std::memchr(guess, '\n', static_cast<size_t>(end - guess));
      if (line_break != nullptr) stop = static_cast<const char*>(line_break) + 1;
    }
    RowPiece piece;
    piece.begin = start;
    piece.end = stop;
    pieces.push_back(piece);
    start = stop;
  }
  return pieces;
}

void CountAndParseOnTwoThreads(std::vector<RowPiece>& pieces, const std::function<void(size_t)>& parse) {
  // First every piece's rows are counted, so that each knows its first frame; then the
  // pieces are parsed. Both steps hand out pieces in order from one counter each.
  std::atomic<size_t> next_count{0}, next_parse{0}, counted{0};
  OnBothThreads([&] {
    if (const size_t i = next_count++; i < pieces.size()) {
      pieces[i].rows = CountRows(pieces[i].begin, pieces[i].end);
      ++counted;
      return true;
    }
    while (counted.load() < pieces.size()) std::this_thread::yield();  // the other thread's last count
    const size_t i = next_parse++;
    if (i >= pieces.size()) return false;
    int64_t first_frame = 0;
    for (size_t k = 0; k < i; ++k) first_frame += pieces[k].rows;
    pieces[i].first_frame = first_frame;
    parse(i);
    return true;
  });
}

bool PieceMustBeNegated(const Eigen::Quaterniond& first, const Eigen::Quaterniond& before_last,
                        const Eigen::Vector4d* before_packed) {
  const double sign1 = first.coeffs().dot(before_last.coeffs()) < 0.0 ? -1.0 : 1.0;
  if (before_packed == nullptr) return sign1 < 0.0;
  const Eigen::Vector4d v = sign1 * Eigen::Vector4d(first.x(), first.y(), first.z(), first.w()).normalized();
  const double sign2 = v.dot(*before_packed) < 0 ? -1.0 : 1.0;
  return sign1 * sign2 < 0.0;
}

bool ParseRowsIntoClip(std::string_view rows_text, const std::vector<JointSampler>& samplers,
                       const std::vector<bvh::rows::ChannelGroup>& groups, int channels, int64_t declared_frames,
                       MotionClip& clip) {
  if (rows_text.size() < kParallelRowsMinBytes) return false;
  const size_t joints = samplers.size();
  // Every value takes at least two bytes: a declared count beyond that is not trusted.
  const int64_t max_rows = static_cast<int64_t>(rows_text.size() / (2 * static_cast<size_t>(channels))) + 1;
  if (declared_frames <= 0 || declared_frames > max_rows ||
      static_cast<size_t>(declared_frames) * joints > bvh::rows::kMaxJointFrames)
    return false;
  // Eigen's default constructors leave coefficients alone: sizing touches no memory.
  clip.rotations.resize(declared_frames * joints);
  clip.translations.resize(declared_frames * joints);

  std::vector<RowPiece> pieces = SplitIntoPieces(rows_text);
  std::vector<PieceParse> parsed(pieces.size());
  CountAndParseOnTwoThreads(pieces, [&](size_t i) {
    const int64_t limit = std::min(declared_frames, pieces[i].first_frame + pieces[i].rows);
    ClipSink sink(clip, joints, pieces[i].first_frame, limit);
    parsed[i] = ParsePiece(pieces[i], limit, samplers, groups, channels, /*every_translation=*/true, sink);
  });
  int64_t frames = 0;
  for (size_t i = 0; i < pieces.size(); ++i) {
    if (!parsed[i].ok || parsed[i].rows != pieces[i].rows) return false;
    frames += pieces[i].rows;
  }
  if (frames == 0 || frames > declared_frames) return false;

  // In order, so that each piece's frame before is final when it is joined.
  for (size_t i = 1; i < pieces.size(); ++i) {
    const int64_t begin = pieces[i].first_frame, end = begin + pieces[i].rows;
    if (begin == end || begin == 0) continue;
    for (size_t j = 0; j < joints; ++j) {
      const Eigen::Quaterniond& before = clip.rotations[(begin - 1) * joints + j];
      if (!PieceMustBeNegated(clip.rotations[begin * joints + j], before, nullptr)) continue;
      for (int64_t f = begin; f < end; ++f) {
        Eigen::Quaterniond& q = clip.rotations[f * joints + j];
        q.coeffs() = -q.coeffs();
      }
    }
  }
  clip.rotations.resize(frames * joints);
  clip.translations.resize(frames * joints);
  clip.num_frames = static_cast<int>(frames);
  return true;
}

}  // namespace mocapfill::fast_convert
