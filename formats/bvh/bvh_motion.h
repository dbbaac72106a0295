// The MOTION section of a BVH file: the Frames / Frame Time header, then one row of
// channel values per frame, converted straight into local joint transforms (file units).
#pragma once

#include <cstdint>
#include <string>

#include "formats/bvh/bvh_hierarchy.h"
#include "formats/bvh/bvh_lexer.h"
#include "formats/bvh/bvh_reader.h"
#include "processing/core/motion_clip.h"
#include "processing/core/status.h"

namespace mocapfill::bvh {

struct MotionHeader {
  int64_t declared_frames = 0;
  TextLocation frames_location;  // of the Frames value
  double frame_time_s = 0.0;
  std::string frame_time_text;   // exactly as written (".0083333")
};

// Parses "Frames: N" and "Frame Time: t" after the MOTION keyword.
Result<MotionHeader> ParseMotionHeader(BvhLexer& lexer);

// Parses every frame row up to the end of the text into `clip` (rotations, already
// hemisphere-continuous, and translations in file units; num_frames and num_joints set). A row that ends early, holds
// too many values, or a value that is not a finite number is an error with line:col.
// `parse_rows`, when given, is tried first (bvh_reader.h: MotionRowsParser).
Status ParseMotionRows(BvhLexer& lexer, const ParsedHierarchy& hierarchy, const MotionHeader& header,
                       MotionClip& clip, MotionRowsParser parse_rows = nullptr);

}  // namespace mocapfill::bvh
