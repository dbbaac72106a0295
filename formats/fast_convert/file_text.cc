#include "formats/fast_convert/file_text.h"

#include <signal.h>
#include <sys/mman.h>
#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <utility>

#include "formats/file_reading.h"

namespace mocapfill {

namespace {

// The mappings the SIGBUS guard answers for. A fixed table, because the handler may only
// read memory that nothing allocates or frees under it; a batch maps at most one file per
// worker at a time, far fewer than this.
struct GuardSlot {
  std::atomic<bool> used{false};
  std::atomic<uintptr_t> begin{0};
  std::atomic<uintptr_t> end{0};  // page-rounded
  std::atomic<bool> lost{false};
};
constexpr int kGuardSlots = 64;
GuardSlot g_slots[kGuardSlots];
struct sigaction g_previous_bus_action {};

uintptr_t PageBytes() {
  static const uintptr_t page = static_cast<uintptr_t>(::sysconf(_SC_PAGESIZE));
  return page;
}

// A fault inside a guarded mapping means its file lost the page (truncated): zero-filled
// pages from there to the mapping's end take its place and the slot is marked, so the
// faulting load reads a zero and parsing runs on to a failure the caller then ignores.
// Any other SIGBUS gets the disposition there was before, and the repeated fault meets it.
void OnBusError(int, siginfo_t* info, void*) {
  const uintptr_t address = reinterpret_cast<uintptr_t>(info->si_addr);
  for (GuardSlot& slot : g_slots) {
    if (!slot.used.load(std::memory_order_acquire)) continue;
    const uintptr_t begin = slot.begin.load(std::memory_order_relaxed);
    const uintptr_t end = slot.end.load(std::memory_order_relaxed);
    if (address < begin || address >= end) continue;
    const uintptr_t page = address & ~(PageBytes() - 1);
    void* zeros =
        ::mmap(reinterpret_cast<void*>(page), end - page, PROT_READ, MAP_PRIVATE | MAP_ANONYMOUS | MAP_FIXED, -1, 0);
    if (zeros == MAP_FAILED) break;
    slot.lost.store(true, std::memory_order_release);
    return;
  }
  ::sigaction(SIGBUS, &g_previous_bus_action, nullptr);
}

bool InstallGuard() {
  static const bool installed = [] {
    (void)PageBytes();  // computed here, not first in the handler
    struct sigaction action {};
    action.sa_sigaction = OnBusError;
    action.sa_flags = SA_SIGINFO;
    sigemptyset(&action.sa_mask);
    return ::sigaction(SIGBUS, &action, &g_previous_bus_action) == 0;
  }();
  return installed;
}

int ClaimSlot(uintptr_t begin, uintptr_t end) {
  for (int i = 0; i < kGuardSlots; ++i) {
    bool expected = false;
    if (!g_slots[i].used.load(std::memory_order_relaxed) &&
        g_slots[i].used.compare_exchange_strong(expected, true, std::memory_order_acq_rel)) {
      // Claimed with used = true before the range is set: until then the range is the
      // previous (unmapped) one or 0, which no fault of a live mapping can fall in.
      g_slots[i].lost.store(false, std::memory_order_relaxed);
      g_slots[i].begin.store(begin, std::memory_order_relaxed);
      g_slots[i].end.store(end, std::memory_order_release);
      return i;
    }
  }
  return -1;
}

}  // namespace

std::optional<FileText> FileText::Map(int fd, size_t bytes) {
  if (bytes == 0 || !InstallGuard()) return std::nullopt;
  void* mapping = ::mmap(nullptr, bytes, PROT_READ, MAP_PRIVATE | MAP_POPULATE, fd, 0);
  if (mapping == MAP_FAILED) return std::nullopt;
  const uintptr_t begin = reinterpret_cast<uintptr_t>(mapping);
  const uintptr_t page = PageBytes();
  const int slot = ClaimSlot(begin, begin + (bytes + page - 1) / page * page);
  if (slot < 0) {
    ::munmap(mapping, bytes);
    return std::nullopt;
  }
  FileText text;
  text.mapping_ = static_cast<const char*>(mapping);
  text.mapping_bytes_ = bytes;
  text.slot_ = slot;
  return text;
}

FileText::FileText(FileText&& other) noexcept
    : buffer_(std::move(other.buffer_)),
      mapping_(std::exchange(other.mapping_, nullptr)),
      mapping_bytes_(std::exchange(other.mapping_bytes_, 0)),
      slot_(std::exchange(other.slot_, -1)) {}

FileText& FileText::operator=(FileText&& other) noexcept {
  if (this != &other) {
    Release();
    buffer_ = std::move(other.buffer_);
    mapping_ = std::exchange(other.mapping_, nullptr);
    mapping_bytes_ = std::exchange(other.mapping_bytes_, 0);
    slot_ = std::exchange(other.slot_, -1);
  }
  return *this;
}

FileText::~FileText() { Release(); }

void FileText::Release() {
  if (slot_ < 0) return;
  // The slot is given up first: the guard must not answer for an address range that is
  // about to be unmapped and may be reused by anything.
  char* const mapping = const_cast<char*>(mapping_);
  const size_t bytes = mapping_bytes_;
  LeaveToExit();
  ::munmap(mapping, bytes);
}

void FileText::LeaveToExit() {
  if (slot_ < 0) return;
  g_slots[slot_].used.store(false, std::memory_order_release);  // nothing reads it any more
  mapping_ = nullptr;
  mapping_bytes_ = 0;
  slot_ = -1;
}

std::string_view FileText::view() const {
  if (slot_ >= 0) return {mapping_, mapping_bytes_};
  return buffer_.view();
}

bool FileText::intact() const { return slot_ < 0 || !g_slots[slot_].lost.load(std::memory_order_acquire); }

Result<LargeBuffer> ReadFileToBuffer(const std::string& path) { return file_reading::ReadWhole<LargeBuffer>(path); }

Result<FileText> ReadFileText(const std::string& path, size_t map_min_bytes) {
  FileDescriptor fd(-1);
  ASSIGN_OR_RETURN(const struct stat info, file_reading::OpenForReading(path, fd));
  if (S_ISREG(info.st_mode) && info.st_size > 0 && static_cast<size_t>(info.st_size) >= map_min_bytes)
    if (std::optional<FileText> text = FileText::Map(fd.get(), static_cast<size_t>(info.st_size)))
      return std::move(*text);
  ASSIGN_OR_RETURN(LargeBuffer bytes, file_reading::ReadOpened<LargeBuffer>(fd, info, path));
  return FileText(std::move(bytes));
}

}  // namespace mocapfill
