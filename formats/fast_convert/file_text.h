// A whole input text, mapped from the page cache when that is cheaper than copying it.
// Reading a large file into a fresh buffer zeroes its pages and copies the text; mapping it
// does neither (docs/performance.md).
//
// A mapped file that another process truncates while it is being parsed would end the
// process with SIGBUS. Instead, a guard installed with the first mapping puts zero-filled
// pages where the lost ones were and marks the text as not intact; the caller throws away
// whatever it derived from it and reads the file again (ReadFileToBuffer), which then
// reports the truncated text as it now is.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include "formats/fast_convert/large_buffer.h"
#include "processing/core/status.h"

namespace mocapfill {

class FileText {
 public:
  FileText() = default;
  explicit FileText(LargeBuffer bytes) : buffer_(std::move(bytes)) {}
  FileText(FileText&& other) noexcept;
  FileText& operator=(FileText&& other) noexcept;
  FileText(const FileText&) = delete;
  FileText& operator=(const FileText&) = delete;
  ~FileText();

  // Maps `bytes` bytes of the open regular file `fd` read-only, every page at once, under
  // the truncation guard; nullopt when the kernel refuses or every guard slot is taken.
  static std::optional<FileText> Map(int fd, size_t bytes);

  std::string_view view() const;
  bool mapped() const { return slot_ >= 0; }
  // False once a page of the mapping vanished under it (the file was truncated meanwhile)
  // and zeros stood in for it: anything parsed from view() must be discarded.
  bool intact() const;

  // Gives up the text without unmapping it: the mapping stays until the process exits.
  // The text is empty afterwards.
  void LeaveToExit();

 private:
  void Release();

  LargeBuffer buffer_;             // when read
  const char* mapping_ = nullptr;  // when mapped: the mapping, its length, its guard slot
  size_t mapping_bytes_ = 0;
  int slot_ = -1;
};

// Regular files of at least this size are mapped by ReadFileText.
inline constexpr size_t kMapFileMinBytes = size_t{1} << 20;
// The same for an input the process leaves mapped until it exits (ConvertOptions::
// leave_input_to_exit): no munmap follows, and mapping costs one call where a read costs a
// page fault per 4 KiB of the fresh buffer it fills. Many inputs in one process stay at
// kMapFileMinBytes: there every munmap flushes the other workers' TLBs.
inline constexpr size_t kMapLeftInputMinBytes = size_t{16} << 10;

// The whole file into a LargeBuffer. Fails as ReadFileBytes (file_io.h).
Result<LargeBuffer> ReadFileToBuffer(const std::string& path);

// The file's bytes for parsing: a regular file of at least `map_min_bytes` mapped
// read-only (check intact() after use), anything else, or a file that cannot be mapped,
// read as ReadFileToBuffer reads it. Fails with kIoError naming the path.
Result<FileText> ReadFileText(const std::string& path, size_t map_min_bytes = kMapFileMinBytes);

}  // namespace mocapfill
