// Terminal output of the CLI: errors and warnings on stderr, and a progress bar that is
// drawn only when stderr is a terminal (so logs and CI output stay quiet).
#pragma once

#include <atomic>
#include <mutex>
#include <string>

#include "processing/core/status.h"

namespace mocapfill::cli {

// Prints "error: <message>" on stderr.
void PrintError(const std::string& message);
// Prints "warning: <message>" on stderr unless quiet.
void PrintWarning(const std::string& message);
void SetQuiet(bool quiet);
bool IsQuiet();

// A thread-safe progress counter; draws "label [=====     ] n/total" on a TTY only.
class Progress {
 public:
  Progress(std::string label, size_t total);
  ~Progress();
  void Advance(size_t n = 1);

 private:
  void Draw(size_t done);
  std::string label_;
  size_t total_;
  std::atomic<size_t> done_{0};
  bool enabled_;
  std::mutex mutex_;
};

}  // namespace mocapfill::cli
