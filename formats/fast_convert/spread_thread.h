// A helper thread that starts on another CPU than the one that starts it. Kernels of small
// VMs (sched_vcpu_pack) put a new thread on the busy vCPU rather than wake an idle one, so a
// std::thread started for half of a parse would share the parser's vCPU until the load
// balancer moved it, most of a short parallel parse. Born with an affinity that leaves the
// current CPU out, the thread goes straight to another one; once running it takes back the
// starting thread's mask, so the scheduler may still move it wherever it likes later.
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
