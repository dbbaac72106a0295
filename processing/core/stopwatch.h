// Wall time of a stage, for the timings the reports give.
#pragma once

#include <chrono>

namespace mocapfill {

// Seconds from `start` (std::chrono::steady_clock::now() when the stage began) to now.
inline double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace mocapfill
