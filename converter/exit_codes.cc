#include "converter/exit_codes.h"

#include "converter/console.h"

namespace mocapfill::cli {

ExitCode ExitCodeFor(const Status& status, Stage stage) { return static_cast<ExitCode>(FailureClass(status, stage)); }

int Fail(const Status& status, Stage stage) {
  PrintError(status.message());
  return ExitCodeFor(status, stage);
}

}  // namespace mocapfill::cli
