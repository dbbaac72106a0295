#include "converter/exit_codes.h"

#include "converter/console.h"

namespace mocapfill::cli {

ExitCode ExitCodeFor(const Status& status, Stage stage) {
  switch (status.code()) {
    case ErrorCode::kOk: return kExitOk;
    case ErrorCode::kInvalidArgument: return kExitUsage;
    case ErrorCode::kInvalidData:
    case ErrorCode::kUnsupported: return stage == Stage::kOutput ? kExitOutput : kExitInvalidInput;
    case ErrorCode::kIoError: return stage == Stage::kOutput ? kExitOutput : kExitInvalidInput;
    case ErrorCode::kNumericalFailure:
    case ErrorCode::kInternal: return kExitProcessing;
  }
  return kExitProcessing;
}

int Fail(const Status& status, Stage stage) {
  PrintError(status.message());
  return ExitCodeFor(status, stage);
}

}  // namespace mocapfill::cli
