#include "formats/assimp/isolated_read.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <new>

#include "formats/assimp/scene_wire.h"

#if defined(__SANITIZE_ADDRESS__)
#define MOCAPFILL_ISOLATION_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MOCAPFILL_ISOLATION_UNDER_ASAN 1
#endif
#endif

namespace mocapfill {

namespace {

// The child's exit code when an allocation fails (its new-handler ends it at once: unwinding
// through a third-party reader that ran out of memory helps no one).
constexpr int kChildOutOfMemory = 86;
// The child's exit code when it cannot hand its answer back.
constexpr int kChildCannotAnswer = 87;

void EndChildOutOfMemory() { _exit(kChildOutOfMemory); }

bool WriteAll(int fd, const std::string& bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

[[noreturn]] void RunChild(int answer_fd, const IsolationLimits& limits, const std::function<Result<Scene>()>& read) {
  prctl(PR_SET_PDEATHSIG, SIGKILL);  // a parent that dies takes the reader with it
  // The parent's handlers are not the child's: a signal must not run the parent's clean-up of
  // its temporary files, and a crash must end the child plainly (a sanitizer's handler would
  // turn it into an exit code).
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE, SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT})
    signal(sig, SIG_DFL);
  // Only the answer pipe stays open: a sibling reader must not hold another one's pipe.
  if (answer_fd > 3) close_range(3, answer_fd - 1, 0);
  close_range(answer_fd + 1, ~0U, 0);
  if (const int null = open("/dev/null", O_RDWR | O_CLOEXEC); null >= 0) {
    dup2(null, STDIN_FILENO);
    dup2(null, STDOUT_FILENO);  // stdout may be the converted file (-o -)
    dup2(null, STDERR_FILENO);  // the runtime's last words ("terminate called ...") are not the user's
  }
  const rlimit no_core{0, 0};
  setrlimit(RLIMIT_CORE, &no_core);
#ifndef MOCAPFILL_ISOLATION_UNDER_ASAN
  if (limits.memory_mb > 0) {
    const rlim_t bytes = static_cast<rlim_t>(limits.memory_mb) << 20;
    const rlimit memory{bytes, bytes};
    setrlimit(RLIMIT_AS, &memory);
  }
#endif
  std::set_new_handler(EndChildOutOfMemory);
  const Result<Scene> scene = read();
  _exit(WriteAll(answer_fd, EncodeSceneResult(scene)) ? 0 : kChildCannotAnswer);
}

// Reads the child's answer until it closes the pipe; false when the deadline passes first.
bool ReadAnswer(int fd, std::chrono::steady_clock::time_point deadline, std::string& bytes) {
  char buffer[1 << 16];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, static_cast<int>(std::min<long long>(left.count() + 1, 1 << 30)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) continue;  // the loop's clock decides
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;  // closed (or broken): the child has ended
    bytes.append(buffer, static_cast<size_t>(n));
  }
}

std::string Seconds(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", s);
  return text;
}

}  // namespace

IsolationLimits IsolationLimitsFromEnvironment() {
  IsolationLimits limits;
  if (const char* v = std::getenv("MOCAPFILL_ASSIMP_MEMORY_MB")) {
    char* end = nullptr;
    const long mb = std::strtol(v, &end, 10);
    if (end != v && *end == '\0' && mb > 0) limits.memory_mb = mb;
  }
  if (const char* v = std::getenv("MOCAPFILL_ASSIMP_TIMEOUT_S")) {
    char* end = nullptr;
    const double s = std::strtod(v, &end);
    if (end != v && *end == '\0' && std::isfinite(s) && s > 0) limits.timeout_s = s;
  }
  return limits;
}

Result<Scene> ReadIsolated(const std::string& path, const IsolationLimits& limits,
                           const std::function<Result<Scene>()>& read) {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) return IoError(path + ": cannot start the isolated reader: " + std::strerror(errno));
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                             std::chrono::duration<double>(std::min(limits.timeout_s, 1e7)));
#ifdef MOCAPFILL_ISOLATION_UNDER_ASAN
  const bool memory_limited = false;
#else
  const bool memory_limited = limits.memory_mb > 0;
#endif
  const pid_t pid = fork();
  if (pid < 0) {
    const int error = errno;
    close(fds[0]);
    close(fds[1]);
    return IoError(path + ": cannot start the isolated reader: " + std::strerror(error));
  }
  if (pid == 0) {
    close(fds[0]);
    RunChild(fds[1], limits, read);
  }
  close(fds[1]);
  std::string bytes;
  const bool finished = ReadAnswer(fds[0], deadline, bytes);
  close(fds[0]);
  if (!finished) kill(pid, SIGKILL);
  int status = 0;
  rusage usage{};
  while (wait4(pid, &status, 0, &usage) < 0 && errno == EINTR) {
  }
  // A crash is put down to memory only when the child had used much of its limit (Assimp also
  // aborts on damaged files, with little memory in use).
  const bool near_memory_limit = memory_limited && usage.ru_maxrss * 1024.0 > 0.5 * limits.memory_mb * 1048576.0;
  const std::string reader = path + ": the Assimp reader ";
  const std::string memory_limit = memory_limited ? " (limit " + std::to_string(limits.memory_mb) +
                                                        " MiB; MOCAPFILL_ASSIMP_MEMORY_MB sets it)"
                                                  : std::string();
  if (!finished)
    return InvalidData(reader + "took longer than " + Seconds(limits.timeout_s) +
                       " s on this file and was stopped (MOCAPFILL_ASSIMP_TIMEOUT_S sets the limit)");
  if (WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    if (sig == SIGKILL)
      return InvalidData(reader + "was killed (SIGKILL) while reading this file, most likely for want of memory");
    // Assimp's C++ runtime is not ours (the plug-in links the shared libstdc++), so an
    // allocation failing inside it can end in abort() rather than in our new-handler, and a
    // stack that cannot grow ends in SIGSEGV.
    const std::string maybe_memory = near_memory_limit ? ", perhaps for want of memory" + memory_limit : std::string();
    return InvalidData(reader + "crashed on this file (signal " + std::to_string(sig) + ", " + strsignal(sig) + ")" +
                       maybe_memory + "; the file is damaged or uses something Assimp cannot read");
  }
  const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (code == kChildOutOfMemory) return InvalidData(reader + "ran out of memory on this file" + memory_limit);
  if (code != 0) return InvalidData(reader + "ended with exit code " + std::to_string(code) + " on this file");
  Result<Scene> scene = DecodeSceneResult(bytes, path);
  // Assimp catches its own std::bad_alloc and reports it as the file's error.
  if (!scene.ok() && scene.status().message().find("std::bad_alloc") != std::string::npos)
    return InvalidData(reader + "ran out of memory on this file" + memory_limit);
  return scene;
}

}  // namespace mocapfill
