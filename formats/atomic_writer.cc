#include "formats/atomic_writer.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <utility>

#include "formats/file_descriptor.h"

namespace mocapfill {

namespace {

// Spares to remove if the process is interrupted. A fixed table of fixed buffers, because
// a signal handler may only read memory that nothing allocates or frees under it. The flags
// lie apart from the paths, so that looking for a free slot touches one page, not one per slot.
constexpr int kCleanupSlots = 64;
constexpr size_t kCleanupPathBytes = 4096;
std::atomic<bool> g_cleanup_used[kCleanupSlots];
std::atomic<bool> g_cleanup_armed[kCleanupSlots];
char g_cleanup_paths[kCleanupSlots][kCleanupPathBytes];

void RemoveSparesThenDie(int signal_number) {
  for (int i = 0; i < kCleanupSlots; ++i)
    if (g_cleanup_armed[i].load(std::memory_order_acquire)) ::unlink(g_cleanup_paths[i]);
  ::signal(signal_number, SIG_DFL);
  ::raise(signal_number);
}

// Installs the handler for the signals that still have their default action (a program
// that handles or ignores one itself keeps doing so); false when none could be covered.
bool InstallCleanup() {
  static const bool installed = [] {
    bool any = false;
    for (int signal_number : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction previous {};
      if (::sigaction(signal_number, nullptr, &previous) != 0 || previous.sa_handler != SIG_DFL) continue;
      struct sigaction action {};
      action.sa_handler = RemoveSparesThenDie;
      sigemptyset(&action.sa_mask);
      any = ::sigaction(signal_number, &action, nullptr) == 0 || any;
    }
    return any;
  }();
  return installed;
}

int ArmCleanup(const std::string& path) {
  if (path.size() >= kCleanupPathBytes || !InstallCleanup()) return -1;
  for (int i = 0; i < kCleanupSlots; ++i) {
    bool expected = false;
    if (g_cleanup_used[i].compare_exchange_strong(expected, true, std::memory_order_acq_rel)) {
      std::memcpy(g_cleanup_paths[i], path.c_str(), path.size() + 1);
      g_cleanup_armed[i].store(true, std::memory_order_release);
      return i;
    }
  }
  return -1;
}

void DisarmCleanup(int slot) {
  if (slot < 0) return;
  g_cleanup_armed[slot].store(false, std::memory_order_release);
  g_cleanup_used[slot].store(false, std::memory_order_release);
}

bool IsRegularFile(const std::string& path) {
  struct stat existing {};
  return ::lstat(path.c_str(), &existing) == 0 && S_ISREG(existing.st_mode);
}

// Swaps the finished `tmp` with the regular file at `path` (renameat2 RENAME_EXCHANGE):
// the old file is then at `tmp`. A plain rename over an existing file makes ext4 start
// writing the new file's data out before it returns (its auto_da_alloc rule), a wait that is a
// sizeable part of a small conversion; the swap does not. False when there is no regular file
// at `path` or the swap is unsupported (other file systems, old kernels).
bool SwapIntoPlace(const std::string& tmp, const std::string& path) {
  return IsRegularFile(path) && ::renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, path.c_str(), RENAME_EXCHANGE) == 0;
}

bool WriteParts(int fd, std::initializer_list<std::string_view> parts, size_t* total) {
  *total = 0;
  for (std::string_view part : parts) {
    if (!WriteAll(fd, part)) return false;
    *total += part.size();
  }
  return true;
}

std::string FolderOf(const std::string& path) { return std::filesystem::path(path).parent_path().string(); }

}  // namespace

AtomicWriter::~AtomicWriter() { DropSpare(); }

void AtomicWriter::ForgetSpare() {
  DisarmCleanup(cleanup_slot_);
  cleanup_slot_ = -1;
  spare_.clear();
}

void AtomicWriter::DropSpare() {
  if (spare_.empty()) return;
  const std::string spare = std::move(spare_);
  ForgetSpare();            // disarmed before the unlink, so an interruption cannot unlink a later file of that name
  ::unlink(spare.c_str());  // if this fails, a stale temporary is all that is left
}

void AtomicWriter::KeepSpare(std::string tmp, std::string folder) {
  DropSpare();
  cleanup_slot_ = ArmCleanup(tmp);
  if (cleanup_slot_ < 0) {  // nothing would remove it if the process were interrupted
    ::unlink(tmp.c_str());
    return;
  }
  spare_ = std::move(tmp);
  spare_folder_ = std::move(folder);
}

// Overwrites the spare with `parts` and moves it into place; false (spare dropped, nothing
// at `path` changed) when the spare cannot serve.
bool AtomicWriter::WriteOverSpare(const std::string& path,
                                  const std::string& folder,
                                  std::initializer_list<std::string_view> parts) {
  if (spare_.empty() || folder != spare_folder_ || new_file_mode_ == 0) return false;
  FileDescriptor fd(::open(spare_.c_str(), O_WRONLY | O_CLOEXEC | O_NOFOLLOW));
  struct stat info {};
  bool ok = fd.get() >= 0 && ::fstat(fd.get(), &info) == 0 && S_ISREG(info.st_mode) && info.st_nlink == 1 &&
            info.st_uid == ::geteuid();
  // Nobody else may have it open: a reader (or a mapping) of the file it was must keep
  // reading that file, as after a rename over it. A write lease is granted only when no
  // other open file refers to it; released at once, it serves as that test (no new open
  // can find it later: only this writer knows its temporary name).
  ok = ok && ::fcntl(fd.get(), F_SETLEASE, F_WRLCK) == 0 && ::fcntl(fd.get(), F_SETLEASE, F_UNLCK) == 0;
  if (ok && (info.st_mode & 07777) != new_file_mode_) ok = ::fchmod(fd.get(), new_file_mode_) == 0;
  // Written over from the start and then cut to length: truncating to zero first would
  // make ext4 write the data out on close (auto_da_alloc, as for a rename over a file).
  size_t total = 0;
  ok = ok && WriteParts(fd.get(), parts, &total) && ::ftruncate(fd.get(), static_cast<off_t>(total)) == 0;
  ok = fd.get() >= 0 && fd.Close() && ok;
  if (!ok) {
    DropSpare();
    return false;
  }
  if (SwapIntoPlace(spare_, path)) return true;  // the replaced file is the spare now
  if (std::rename(spare_.c_str(), path.c_str()) == 0) {
    ForgetSpare();  // it is the output now
    return true;
  }
  DropSpare();
  return false;
}

Status AtomicWriter::Write(const std::string& path, std::initializer_list<std::string_view> parts) {
  const std::string folder = FolderOf(path);
  if (WriteOverSpare(path, folder, parts)) return OkStatus();
  std::string tmp = path + ".tmp-" + std::to_string(::getpid());
  FileDescriptor fd(::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666));
  if (fd.get() < 0) return IoError(path + ": cannot create (" + std::strerror(errno) + ")");
  struct stat info {};
  if (::fstat(fd.get(), &info) == 0) new_file_mode_ = info.st_mode & 07777;
  size_t total = 0;
  const bool written = WriteParts(fd.get(), parts, &total);
  const bool closed = fd.Close();
  if (!written || !closed) {
    std::remove(tmp.c_str());
    return IoError(path + ": write failed");
  }
  if (SwapIntoPlace(tmp, path)) {
    KeepSpare(std::move(tmp), folder);
    return OkStatus();
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(tmp.c_str());
    return IoError(path + ": cannot rename temporary file (" + reason + ")");
  }
  return OkStatus();
}

Status WriteFileAtomic(const std::string& path, const std::string& bytes) {
  return WriteFileAtomicParts(path, {std::string_view(bytes)});
}

Status WriteFileAtomicParts(const std::string& path, std::initializer_list<std::string_view> parts,
                            AtomicWriter* writer) {
  if (writer != nullptr) return writer->Write(path, parts);
  AtomicWriter own;
  return own.Write(path, parts);
}

size_t RemoveStaleTemporaries(const std::string& folder) {
  size_t removed = 0;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    const size_t mark = name.rfind(".tmp-");
    if (mark == std::string::npos || mark == 0 || mark + 5 == name.size()) continue;
    const std::string digits = name.substr(mark + 5);
    if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const pid_t pid = static_cast<pid_t>(std::stol(digits));
    if (pid <= 0 || pid == ::getpid()) continue;
    std::error_code type_ec;
    if (!entry.is_regular_file(type_ec)) continue;
    // ESRCH: no such process. EPERM means another user's live process: keep its file.
    if (::kill(pid, 0) == 0 || errno != ESRCH) continue;
    if (::unlink(entry.path().c_str()) == 0) ++removed;
  }
  return removed;
}

}  // namespace mocapfill
