#include "converter/console.h"

#include <unistd.h>

#include <cstdio>

namespace mocapfill::cli {

namespace {
bool g_quiet = false;
std::mutex g_print_mutex;
}  // namespace

void SetQuiet(bool quiet) { g_quiet = quiet; }
bool IsQuiet() { return g_quiet; }

void PrintError(const std::string& message) {
  std::lock_guard<std::mutex> lock(g_print_mutex);
  std::fprintf(stderr, "error: %s\n", message.c_str());
}

void PrintWarning(const std::string& message) {
  if (g_quiet) return;
  std::lock_guard<std::mutex> lock(g_print_mutex);
  std::fprintf(stderr, "warning: %s\n", message.c_str());
}

Progress::Progress(std::string label, size_t total)
    : label_(std::move(label)), total_(total), enabled_(!g_quiet && total > 1 && ::isatty(STDERR_FILENO)) {
  if (enabled_) Draw(0);
}

Progress::~Progress() {
  if (enabled_) std::fprintf(stderr, "\n");
}

void Progress::Advance(size_t n) {
  const size_t done = done_.fetch_add(n) + n;
  if (enabled_) Draw(done);
}

void Progress::Draw(size_t done) {
  std::lock_guard<std::mutex> lock(mutex_);
  constexpr int kWidth = 30;
  const int filled = total_ ? static_cast<int>(kWidth * done / total_) : kWidth;
  std::fprintf(stderr, "\r%s [%.*s%*s] %zu/%zu", label_.c_str(), filled, "==============================",
               kWidth - filled, "", done, total_);
  std::fflush(stderr);
}

}  // namespace mocapfill::cli
