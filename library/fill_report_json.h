// The fill report as JSON: what `mocapfill fill --report` writes and what the public API
// (and so Python's report dict) returns. One writer, so both say the same.
#pragma once

#include <string>

#include "processing/sketch_fill/sketch_fill.h"

namespace mocapfill {

// `database` names the database in the report; `load_database_s` is its load time (stage
// "load_database"). `indent` < 0 gives one line.
std::string FillReportJson(const SketchFillResult& result, const std::string& database, double load_database_s,
                           int indent = 2);

}  // namespace mocapfill
