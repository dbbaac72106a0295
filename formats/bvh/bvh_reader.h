// BVH (Biovision hierarchy) import: any rotation order and channel layout per joint,
// several roots, End Sites, names with spaces, any line ending; errors carry line:column.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "formats/motion_io.h"

namespace mocapfill {

namespace bvh::rows {
struct JointSampler;
struct ChannelGroup;
}  // namespace bvh::rows

// Parses the rows of a motion section (`rows_text`, the text after the Frame Time line) into
// `clip` by some faster means than the serial loop, with the same result (the convert fast
// path's two-thread parser, formats/fast_convert/rows_in_parallel.h). Returns false to leave
// the rows to the serial loop, which then reports any error with its line and column.
using MotionRowsParser = bool (*)(std::string_view rows_text, const std::vector<bvh::rows::JointSampler>& samplers,
                                  const std::vector<bvh::rows::ChannelGroup>& groups, int channels,
                                  int64_t declared_frames, MotionClip& clip);

// Parses BVH text. `path` only labels messages. Units and axes are resolved per `options`.
// `parse_rows`, when given, is tried on the motion rows before the serial loop.
Result<Scene> ReadBvh(std::string_view text, const std::string& path, const ImportOptions& options,
                      MotionRowsParser parse_rows = nullptr);

}  // namespace mocapfill
