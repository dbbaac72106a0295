// The META section of a .mfdb file: everything except the big matrices, as JSON (skeleton,
// rate, joint means, clips and labels, band list, matrix shapes). Internal to formats/mfdb.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/core/status.h"

namespace mocapfill::mfdb {

// Shapes of the binary sections that follow META, as declared by META.
struct Layout {
  long frames = 0;
  int channels = 0;
  int translation_columns = 0;
  std::vector<int> bands;   // band indices, one BAND section each, in this order
  int correlation_channels = 0;  // 0 = no CORR entries
};

// JSON text of `parts` (matrices excluded). Deterministic: same parts, same bytes.
std::string EncodeMeta(const MotionDatabase::Parts& parts);

// Fills everything but the matrices of `parts` and returns the section shapes.
// Malformed or out-of-range fields give kInvalidData naming the field.
Result<Layout> DecodeMeta(std::string_view json, MotionDatabase::Parts& parts);

}  // namespace mocapfill::mfdb
