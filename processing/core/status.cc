#include "processing/core/status.h"

namespace mocapfill {

const char* ErrorCodeName(ErrorCode code) {
  switch (code) {
    case ErrorCode::kOk: return "ok";
    case ErrorCode::kInvalidArgument: return "invalid argument";
    case ErrorCode::kInvalidData: return "invalid data";
    case ErrorCode::kUnsupported: return "unsupported";
    case ErrorCode::kIoError: return "i/o error";
    case ErrorCode::kNumericalFailure: return "numerical failure";
    case ErrorCode::kInternal: return "internal error";
  }
  return "unknown";
}

}  // namespace mocapfill
