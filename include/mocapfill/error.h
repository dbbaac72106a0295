// Every call of the API reports failure by throwing mocapfill::api::Error: its message names
// the file, line or field and what was expected, and its kind is the exit-code class the
// command-line tool would exit with for the same failure.
#pragma once

#include <stdexcept>
#include <string>

#include "mocapfill/export.h"

namespace mocapfill::api {

// The command-line tool's exit codes (README, "Exit codes").
enum class ErrorKind : int {
  kUsage = 1,         // bad options or arguments
  kInvalidInput = 2,  // an input file is unreadable, malformed or unsupported
  kProcessing = 3,    // processing failed (solver, numerical or internal error)
  kOutput = 4,        // an output file could not be written, or would overwrite an input
};

class MOCAPFILL_API Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  ErrorKind kind() const { return kind_; }
  int exit_code() const { return static_cast<int>(kind_); }

 private:
  ErrorKind kind_;
};

}  // namespace mocapfill::api
