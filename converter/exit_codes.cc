#include "converter/exit_codes.h"

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

}  // namespace mocapfill::cli
