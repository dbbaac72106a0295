// SpreadThread: runs its body, joins, and leaves the thread free to run on every CPU the
// starting thread may use, even when that is a single one.
#include <gtest/gtest.h>

#include <pthread.h>
#include <sched.h>

#include <atomic>
#include <thread>

#include "formats/fast_convert/spread_thread.h"

namespace mocapfill {
namespace {

cpu_set_t ThisThreadsCpus() {
  cpu_set_t cpus;
  CPU_ZERO(&cpus);
  EXPECT_EQ(pthread_getaffinity_np(pthread_self(), sizeof cpus, &cpus), 0);
  return cpus;
}

TEST(SpreadThread, RunsTheBodyAndJoinWaitsForIt) {
  std::atomic<int> runs{0};
  {
    SpreadThread thread([&] {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      ++runs;
    });
    thread.Join();
    EXPECT_EQ(runs.load(), 1);
    thread.Join();  // a second join is a no-op
  }
  {
    SpreadThread joined_by_destructor([&] { ++runs; });
  }
  EXPECT_EQ(runs.load(), 2);
}

TEST(SpreadThread, BodyRunsWithTheStartersWholeCpuMask) {
  const cpu_set_t starter = ThisThreadsCpus();
  cpu_set_t seen;
  CPU_ZERO(&seen);
  SpreadThread thread([&] { seen = ThisThreadsCpus(); });
  thread.Join();
  EXPECT_TRUE(CPU_EQUAL(&seen, &starter)) << CPU_COUNT(&seen) << " of " << CPU_COUNT(&starter) << " CPUs";
}

// Pinned to one CPU (taskset, a one-CPU container), there is nowhere else to go: the
// thread still starts, on that CPU.
TEST(SpreadThread, StartsWhereTheStarterIsWhenThatIsTheOnlyCpu) {
  const cpu_set_t original = ThisThreadsCpus();
  const int here = sched_getcpu();
  ASSERT_GE(here, 0);
  cpu_set_t one;
  CPU_ZERO(&one);
  CPU_SET(here, &one);
  ASSERT_EQ(pthread_setaffinity_np(pthread_self(), sizeof one, &one), 0);
  cpu_set_t seen;
  CPU_ZERO(&seen);
  int ran_on = -1;
  {
    SpreadThread thread([&] {
      seen = ThisThreadsCpus();
      ran_on = sched_getcpu();
    });
  }
  ASSERT_EQ(pthread_setaffinity_np(pthread_self(), sizeof original, &original), 0);
  EXPECT_TRUE(CPU_EQUAL(&seen, &one));
  EXPECT_EQ(ran_on, here);
}

}  // namespace
}  // namespace mocapfill
