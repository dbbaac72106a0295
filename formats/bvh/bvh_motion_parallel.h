// The MOTION rows of a large BVH file parsed on two threads: the text is split at a line
// break near its middle, the rows before the split are counted, and each half is parsed
// straight into its own frames of the clip. The result is bit-identical to the serial
// loop's. Anything irregular (a bad row, rows that do not fit the declared frame count,
// unusual line breaks) makes it give up, and the serial loop parses the file again and
// reports the exact error or warning.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "formats/bvh/bvh_motion_rows.h"
#include "processing/core/motion_clip.h"

namespace mocapfill::bvh {

// Motion text smaller than this is parsed on the calling thread: starting a thread costs
// more than it saves. Converting Bandai clips one process each, a second thread lost
// 4-5% on clips of 128-400 KB and won 1-2% on the twelve of 400-600 KB (paired medians,
// alternating processes); it was 128 KiB when the row loop was slower.
inline constexpr size_t kParallelMotionMinBytes = size_t{384} << 10;

// Rows of `rows_text` from `p` to `end`: lines holding something other than blanks.
int64_t CountRows(const char* p, const char* end);

// `rows_text` split at the first line break past its middle, and the rows before the split.
struct RowSplit {
  const char* split = nullptr;
  int64_t first_rows = 0;
};
// nullopt when there is no line break past the middle or no row before it.
std::optional<RowSplit> SplitRowsInHalf(std::string_view rows_text);

// Parses every row of `rows_text` (the text after the Frame Time line) into `clip`
// (rotations, translations, num_frames). Returns false, with the clip's arrays in an
// unspecified state, when the serial loop must do it instead.
bool ParseMotionRowsInParallel(std::string_view rows_text, const std::vector<rows::JointSampler>& samplers,
                               const std::vector<rows::ChannelGroup>& groups, int channels, int64_t declared_frames,
                               MotionClip& clip);

}  // namespace mocapfill::bvh
