// Runs the mocapfill executable the way a user's shell would, for the CLI tests.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace mocapfill::testing {

struct RunResult {
  int exit_code = -1;  // -1 when the process could not be started or did not exit normally
  std::string output;  // stdout and stderr together
};

// Runs `mocapfill <args>` through the shell (args are shell words) and captures its output.
RunResult RunCli(const std::string& args);

// As RunCli, capturing standard output alone (JSON, piped files); stderr goes to
// `stderr_file`, or is discarded when "".
RunResult RunCliStdout(const std::string& args, const std::string& stderr_file = "");

// Starts `mocapfill args...` directly (no shell), its stdout and stderr into `log` (or
// discarded when ""), and returns without waiting: its pid, -1 when it could not start.
pid_t StartCli(const std::vector<std::string>& args, const std::string& log = "");

struct FinishedRun {
  int exit_code = -1;  // -1 when killed by a signal (or by the time limit)
  bool timed_out = false;
  long max_rss_mb = 0;  // its peak resident memory
};

// Waits for a run StartCli began; kills it with SIGKILL after `limit_s` seconds (0: waits
// as long as it takes).
FinishedRun WaitCli(pid_t pid, int limit_s = 0);

// A whole file's bytes ("" when it cannot be read: the caller's assertions then fail).
std::string ReadAll(const std::string& path);

}  // namespace mocapfill::testing
