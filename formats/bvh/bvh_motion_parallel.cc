#include "formats/bvh/bvh_motion_parallel.h"

#include "formats/file_io.h"
#include "formats/spread_thread.h"

#include <cstring>
#include <optional>
#include <system_error>

namespace mocapfill::bvh {

namespace {

using rows::JointSampler;

struct Chunk {
  bool ok = false;
  int64_t rows = 0;
};

// Parses the rows of [p, end) into frames first_frame, first_frame + 1, ... of `clip`,
// never at or past frame_limit. The chunk's first frame is not matched to the hemisphere
// of the frame before it (another thread may still be writing that one).
Chunk ParseChunk(const char* p, const char* end, const std::vector<JointSampler>& samplers,
                 const std::vector<rows::ChannelGroup>& groups, int channels,
                 int64_t first_frame, int64_t frame_limit, MotionClip& clip) {
  const size_t joints = samplers.size();
  // Each thread maps the pages it is about to fill, so the two share that work too.
  const size_t first = static_cast<size_t>(first_frame) * joints, count = static_cast<size_t>(frame_limit - first_frame) * joints;
  PrefaultForWrite(clip.rotations.data() + first, count * sizeof(Eigen::Quaterniond));
  PrefaultForWrite(clip.translations.data() + first, count * sizeof(Eigen::Vector3d));
  std::vector<double> row(channels);
  rows::FrameComposer composer(samplers, groups);
  rows::RowScanner scanner(groups, channels);
  Chunk chunk;
  for (int64_t frame = first_frame;; ++frame) {
    while (p < end && IsBvhSpace(*p)) ++p;
    if (p == end) {
      chunk.ok = true;
      return chunk;
    }
    if (frame >= frame_limit || scanner.Scan(p, end, row.data()).kind != rows::RowEnd::kComplete)
      return chunk;
    Eigen::Quaterniond* rotations = clip.rotations.data() + frame * joints;
    composer.Compose(scanner, row.data(), frame > first_frame ? rotations - joints : nullptr, rotations,
                       clip.translations.data() + frame * joints);
    ++chunk.rows;
  }
}

// The second chunk's tracks were made continuous from its own first frame; a joint whose
// first frame there lies in the other hemisphere from its last frame before is flipped
// over the whole chunk, which is exactly what the serial loop's frame-by-frame flips give
// (negation is exact, so every later dot product only changes sign).
void JoinHemispheres(const std::vector<JointSampler>& samplers, int64_t split_frame, int64_t frames,
                     MotionClip& clip) {
  const size_t joints = samplers.size();
  for (size_t j = 0; j < joints; ++j) {
    if (samplers[j].num_rotations == 0) continue;
    const Eigen::Quaterniond& before = clip.rotations[(split_frame - 1) * joints + j];
    if (clip.rotations[split_frame * joints + j].coeffs().dot(before.coeffs()) >= 0.0) continue;
    for (int64_t f = split_frame; f < frames; ++f) {
      Eigen::Quaterniond& q = clip.rotations[f * joints + j];
      q.coeffs() = -q.coeffs();
    }
  }
}

}  // namespace

// Rows of a valid motion section: lines holding something other than blanks. (Rows that
// end in a lone CR are undercounted; the parse then disagrees with the count and the
// serial loop takes over.)
int64_t CountRows(const char* p, const char* end) {
  int64_t count = 0;
  while (true) {
    while (p < end && IsBvhSpace(*p)) ++p;
    if (p == end) return count;
    ++count;
    const void* line_break = std::memchr(p, '\n', static_cast<size_t>(end - p));
    p = line_break != nullptr ? static_cast<const char*>(line_break) + 1 : end;
  }
}

std::optional<RowSplit> SplitRowsInHalf(std::string_view rows_text) {
  const char* begin = rows_text.data();
  const void* split_break = std::memchr(begin + rows_text.size() / 2, '\n', rows_text.size() - rows_text.size() / 2);
  if (split_break == nullptr) return std::nullopt;
  RowSplit split;
  split.split = static_cast<const char*>(split_break) + 1;
  split.first_rows = CountRows(begin, split.split);
  if (split.first_rows == 0) return std::nullopt;
  return split;
}

bool ParseMotionRowsInParallel(std::string_view rows_text, const std::vector<JointSampler>& samplers,
                               const std::vector<rows::ChannelGroup>& groups, int channels,
                               int64_t declared_frames, MotionClip& clip) {
  const size_t joints = samplers.size();
  const char* begin = rows_text.data();
  const char* end = begin + rows_text.size();
  const std::optional<RowSplit> halves = SplitRowsInHalf(rows_text);
  if (!halves) return false;
  const char* split = halves->split;
  const int64_t first_rows = halves->first_rows;
  // Every value takes at least two bytes: a declared count beyond that is not trusted.
  const int64_t max_rows = static_cast<int64_t>(rows_text.size() / (2 * static_cast<size_t>(channels))) + 1;
  if (declared_frames <= first_rows || declared_frames > max_rows ||
      static_cast<size_t>(declared_frames) * joints > rows::kMaxJointFrames)
    return false;
  // Eigen's default constructors leave coefficients alone: sizing touches no memory.
  clip.rotations.resize(declared_frames * joints);
  clip.translations.resize(declared_frames * joints);

  Chunk second;
  std::optional<SpreadThread> helper;
  try {
    helper.emplace(
        [&] { second = ParseChunk(split, end, samplers, groups, channels, first_rows, declared_frames, clip); });
  } catch (const std::system_error&) {
    return false;  // no thread to be had: the serial loop does it all
  }
  const Chunk first = ParseChunk(begin, split, samplers, groups, channels, 0, first_rows, clip);
  helper->Join();
  if (!first.ok || first.rows != first_rows || !second.ok) return false;

  const int64_t frames = first_rows + second.rows;
  if (second.rows > 0) JoinHemispheres(samplers, first_rows, frames, clip);
  clip.rotations.resize(frames * joints);
  clip.translations.resize(frames * joints);
  clip.num_frames = static_cast<int>(frames);
  return true;
}

}  // namespace mocapfill::bvh
