// Runs the mocapfill executable the way a user's shell would, for the CLI tests.
#pragma once

#include <string>

namespace mocapfill::testing {

struct RunResult {
  int exit_code = -1;  // -1 when the process could not be started or did not exit normally
  std::string output;  // stdout and stderr together
};

// Runs `mocapfill <args>` through the shell (args are shell words) and captures its output.
RunResult RunCli(const std::string& args);

// A whole file's bytes ("" when it cannot be read: the caller's assertions then fail).
std::string ReadAll(const std::string& path);

}  // namespace mocapfill::testing
