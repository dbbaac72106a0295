#include "library/failure_class.h"

namespace mocapfill {

int FailureClass(const Status& status, FailureStage stage) {
  switch (status.code()) {
    case ErrorCode::kOk: return 0;
    case ErrorCode::kInvalidArgument: return 1;
    case ErrorCode::kInvalidData:
    case ErrorCode::kUnsupported:
    case ErrorCode::kIoError: return stage == FailureStage::kOutput ? 4 : 2;
    case ErrorCode::kNumericalFailure:
    case ErrorCode::kInternal: return 3;
  }
  return 3;
}

}  // namespace mocapfill
