#include "converter/exit_codes.h"

#include "converter/console.h"
#include "library/failure_class.h"

namespace mocapfill::cli {

ExitCode ExitCodeFor(const Status& status, Stage stage) {
  const FailureStage where = stage == Stage::kInput        ? FailureStage::kInput
                             : stage == Stage::kOutput     ? FailureStage::kOutput
                                                           : FailureStage::kProcessing;
  return static_cast<ExitCode>(FailureClass(status, where));
}

int Fail(const Status& status, Stage stage) {
  PrintError(status.message());
  return ExitCodeFor(status, stage);
}

}  // namespace mocapfill::cli
