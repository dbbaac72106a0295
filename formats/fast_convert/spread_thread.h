// A helper thread that starts on another CPU than the one that starts it. The kernels of
// the small VMs mocapfill is measured on pack new threads onto the busy vCPU rather than
// wake an idle one (sched_vcpu_pack), so a std::thread started for the second half of a
// parse often shared the parser's vCPU for 3-4 ms, time-slicing with it, before the load
// balancer moved it: on a 10 ms CMU conversion that is most of the parallel part. Born
// with an affinity that leaves the current CPU out, the thread goes straight to another
// one; once running it takes back the starting thread's mask, so the scheduler may still
// move it wherever it likes later.
#pragma once

#include <functional>

namespace mocapfill {

class SpreadThread {
 public:
  // Starts `body`. Throws std::system_error when no thread can be had (as std::thread).
  explicit SpreadThread(std::function<void()> body);
  SpreadThread(const SpreadThread&) = delete;
  SpreadThread& operator=(const SpreadThread&) = delete;
  ~SpreadThread();  // joins

  void Join();

 private:
  struct State;
  static void* Run(void* state);
  State* state_;
};

}  // namespace mocapfill
