// CPU time of the calling thread, for the in-process bench drivers (bvh_read_bench.cc,
// bvh_ab.cc): a busy machine's scheduling of other work does not count.
#pragma once

#include <time.h>

namespace mocapfill::bench {

inline double ThreadCpuSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace mocapfill::bench
