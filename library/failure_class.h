// Which of the documented exit codes a failure belongs to: the CLI exits with it and the
// public API's Error carries it, so both classify a failure the same way.
#pragma once

#include "processing/core/status.h"

namespace mocapfill {

// Where a failure happened decides between "input" and "output" for I/O errors.
enum class FailureStage { kInput, kProcessing, kOutput };

// 0 ok, 1 usage, 2 invalid input, 3 processing, 4 output (README "Exit codes").
int FailureClass(const Status& status, FailureStage stage);

}  // namespace mocapfill
