#include "formats/fast_convert/spread_thread.h"

#include <pthread.h>
#include <sched.h>

#include <system_error>
#include <utility>

namespace mocapfill {

struct SpreadThread::State {
  std::function<void()> body;
  cpu_set_t starter_cpus;
  bool restore = false;
  pthread_t thread{};
  bool joined = false;
};

void* SpreadThread::Run(void* argument) {
  auto* state = static_cast<State*>(argument);
  if (state->restore) pthread_setaffinity_np(pthread_self(), sizeof state->starter_cpus, &state->starter_cpus);
  state->body();
  return nullptr;
}

SpreadThread::SpreadThread(std::function<void()> body) : state_(new State{std::move(body), {}, false, {}, false}) {
  pthread_attr_t attributes;
  pthread_attr_init(&attributes);
  CPU_ZERO(&state_->starter_cpus);
  const int here = sched_getcpu();
  if (here >= 0 && here < CPU_SETSIZE && sched_getaffinity(0, sizeof state_->starter_cpus, &state_->starter_cpus) == 0) {
    cpu_set_t elsewhere = state_->starter_cpus;
    CPU_CLR(here, &elsewhere);
    // Only one CPU to run on (taskset, a container's cpuset): nothing to spread over.
    if (CPU_COUNT(&elsewhere) > 0 && pthread_attr_setaffinity_np(&attributes, sizeof elsewhere, &elsewhere) == 0)
      state_->restore = true;
  }
  const int error = pthread_create(&state_->thread, &attributes, Run, state_);
  pthread_attr_destroy(&attributes);
  if (error != 0) {
    delete state_;
    throw std::system_error(error, std::generic_category(), "pthread_create");
  }
}

void SpreadThread::Join() {
  if (state_->joined) return;
  pthread_join(state_->thread, nullptr);
  state_->joined = true;
}

SpreadThread::~SpreadThread() {
  Join();
  delete state_;
}

}  // namespace mocapfill
