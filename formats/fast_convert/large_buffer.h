// One block of memory for a whole input text or a whole set of output tracks. Not
// zero-filled, and from 1 MiB up mapped on its own, 2 MiB-aligned and marked for
// transparent huge pages where the kernel offers them (madvise mode, as on Debian). In a
// virtual machine first touching a 4 KiB page is an exit to the hypervisor; 2 MiB pages make
// a large buffer several times cheaper to fault in and to release (docs/performance.md).
#pragma once

#include <cstddef>
#include <string_view>

namespace mocapfill {

class LargeBuffer {
 public:
  LargeBuffer() = default;
  // `bytes` bytes of unspecified content. The buffer is made to be filled, so its small
  // pages are mapped for writing at once (PrefaultForWrite); a huge page is faulted in whole
  // at its first touch. Throws std::bad_alloc when memory is short.
  explicit LargeBuffer(size_t bytes);
  LargeBuffer(LargeBuffer&& other) noexcept;
  LargeBuffer& operator=(LargeBuffer&& other) noexcept;
  LargeBuffer(const LargeBuffer&) = delete;
  LargeBuffer& operator=(const LargeBuffer&) = delete;
  ~LargeBuffer();

  unsigned char* data() { return data_; }
  const unsigned char* data() const { return data_; }
  size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  std::string_view view() const { return {reinterpret_cast<const char*>(data_), size_}; }

  // Changes the size; growing past the capacity moves the bytes to a larger block (the new
  // bytes are unspecified).
  void resize(size_t bytes);

 private:
  void Release();

  unsigned char* data_ = nullptr;
  size_t size_ = 0;
  size_t capacity_ = 0;
  void* mapping_ = nullptr;  // when mapped on its own: the mapping, and its length
  size_t mapping_bytes_ = 0;
};

// Asks the kernel to map the whole pages inside [data, data + bytes) for writing now, in
// one call, instead of one page fault per 4 KiB page on first touch (in a VM each fault is
// an exit to the hypervisor, several times dearer than a page mapped by the call). Only
// worth it for buffers that are about to be written in full. Does
// nothing where the kernel lacks MADV_POPULATE_WRITE.
void PrefaultForWrite(void* data, size_t bytes);

// Makes malloc keep `bytes` free at the top of its heap (M_TOP_PAD: every growth adds that
// much, and trimming leaves it), grows the heap that far now and maps all of it for writing
// in one call. For a short process whose small allocations would otherwise fault in a fresh
// heap page at a time (docs/performance.md).
// Does nothing under AddressSanitizer (its own heap) or without MADV_POPULATE_WRITE.
void ReserveMappedHeap(size_t bytes);

}  // namespace mocapfill
