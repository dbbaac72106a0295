// Running a reader of third-party code (Assimp) in a child process, so that a file which
// makes it crash, hang or exhaust memory ends as an error naming the file, never as a crash
// of mocapfill: the child reads under limits and hands the scene back through a pipe
// (scene_wire.h); the parent waits with a deadline and explains any other ending.
#pragma once

#include <functional>
#include <string>

#include "formats/motion_io.h"

namespace mocapfill {

struct IsolationLimits {
  // Address space of the child, MiB (RLIMIT_AS). 0 = none. Not applied in sanitizer builds,
  // whose shadow memory needs terabytes of address space.
  long memory_mb = 4096;
  // Wall-clock time the child may take, seconds; then it is killed.
  double timeout_s = 300.0;
};

// The limits of the environment: MOCAPFILL_ASSIMP_MEMORY_MB and MOCAPFILL_ASSIMP_TIMEOUT_S
// override the defaults above (positive numbers; anything else is ignored).
IsolationLimits IsolationLimitsFromEnvironment();

// Runs `read` in a forked child under `limits` and returns what it read. When the child
// crashes, is killed, runs out of memory or time, or answers nonsense: kInvalidData naming
// `path` and what happened. Fork or pipe failure: kIoError.
Result<Scene> ReadIsolated(const std::string& path, const IsolationLimits& limits,
                           const std::function<Result<Scene>()>& read);

}  // namespace mocapfill
