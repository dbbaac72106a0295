// Documented exit codes of the mocapfill CLI (see README "Exit codes").
#pragma once

#include "library/failure_class.h"
#include "processing/core/status.h"

namespace mocapfill::cli {

enum ExitCode : int {
  kExitOk = 0,
  kExitUsage = 1,       // bad command line, options or pipeline configuration
  kExitInvalidInput = 2,  // an input file is unreadable, malformed or unsupported
  kExitProcessing = 3,  // processing failed (solver, numerical or internal error)
  kExitOutput = 4,      // an output file could not be written, or would overwrite an input
};

// Where a failure happened decides between "input" and "output" for I/O errors (the API's
// classes are the same: library/failure_class.h).
using Stage = FailureStage;

ExitCode ExitCodeFor(const Status& status, Stage stage);

// Prints the status as an error on stderr and returns its exit code.
int Fail(const Status& status, Stage stage);

}  // namespace mocapfill::cli
