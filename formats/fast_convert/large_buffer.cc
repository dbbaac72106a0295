#include "formats/fast_convert/large_buffer.h"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <new>
#include <utility>

namespace mocapfill {

namespace {

constexpr size_t kHugePage = size_t{2} << 20;
constexpr size_t kOwnMappingMinBytes = size_t{1} << 20;
// A huge page is zeroed whole at its first touch, about a hundred times the cost of a small
// page's fault: a last huge page holding less than this much of the buffer is cheaper as
// small pages.
constexpr size_t kHugeTailMinBytes = size_t{400} << 10;

size_t RoundUp(size_t bytes, size_t to) { return (bytes + to - 1) / to * to; }

}  // namespace

LargeBuffer::LargeBuffer(size_t bytes) : size_(bytes), capacity_(bytes) {
  if (bytes < kOwnMappingMinBytes) {
    data_ = static_cast<unsigned char*>(std::malloc(bytes > 0 ? bytes : 1));
    if (data_ == nullptr) throw std::bad_alloc();
    // From 128 KiB malloc maps a fresh block, and a read into one would fault once per page.
    PrefaultForWrite(data_, bytes);
    return;
  }
  // Over-map by one huge page, then trim to a 2 MiB-aligned span, so that every 2 MiB of
  // it can be one page.
  const size_t span = RoundUp(bytes, kHugePage);
  void* raw = ::mmap(nullptr, span + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (raw == MAP_FAILED) throw std::bad_alloc();
  const uintptr_t begin = reinterpret_cast<uintptr_t>(raw);
  const uintptr_t aligned = RoundUp(begin, kHugePage);
  if (aligned > begin) ::munmap(raw, aligned - begin);
  const uintptr_t end = begin + span + kHugePage;
  if (end > aligned + span) ::munmap(reinterpret_cast<void*>(aligned + span), end - (aligned + span));
  mapping_ = reinterpret_cast<void*>(aligned);
  mapping_bytes_ = span;
  capacity_ = span;
  const size_t tail = bytes % kHugePage;
  const size_t huge = tail >= kHugeTailMinBytes ? span : span - (tail > 0 ? kHugePage : 0);
  (void)huge;  // unused where the kernel headers know neither advice
#ifdef MADV_HUGEPAGE
  if (huge > 0) ::madvise(mapping_, huge, MADV_HUGEPAGE);  // a hint: without huge pages, small ones serve
  // The rest stays in small pages where THP is "madvise"; under "always" say so.
  if (huge < span) ::madvise(static_cast<char*>(mapping_) + huge, span - huge, MADV_NOHUGEPAGE);
#endif
#ifdef MADV_POPULATE_WRITE
  // The buffer is made to be filled: its small pages in one call rather than a fault each.
  constexpr size_t kSmallPage = 4096;
  if (huge < bytes) ::madvise(static_cast<char*>(mapping_) + huge, RoundUp(bytes - huge, kSmallPage), MADV_POPULATE_WRITE);
#endif
  data_ = static_cast<unsigned char*>(mapping_);
}

LargeBuffer::LargeBuffer(LargeBuffer&& other) noexcept
    : data_(std::exchange(other.data_, nullptr)),
      size_(std::exchange(other.size_, 0)),
      capacity_(std::exchange(other.capacity_, 0)),
      mapping_(std::exchange(other.mapping_, nullptr)),
      mapping_bytes_(std::exchange(other.mapping_bytes_, 0)) {}

LargeBuffer& LargeBuffer::operator=(LargeBuffer&& other) noexcept {
  if (this != &other) {
    Release();
    data_ = std::exchange(other.data_, nullptr);
    size_ = std::exchange(other.size_, 0);
    capacity_ = std::exchange(other.capacity_, 0);
    mapping_ = std::exchange(other.mapping_, nullptr);
    mapping_bytes_ = std::exchange(other.mapping_bytes_, 0);
  }
  return *this;
}

LargeBuffer::~LargeBuffer() { Release(); }

void LargeBuffer::Release() {
  if (mapping_ != nullptr) {
    ::munmap(mapping_, mapping_bytes_);
  } else {
    std::free(data_);
  }
  data_ = nullptr;
  mapping_ = nullptr;
  size_ = capacity_ = mapping_bytes_ = 0;
}

void PrefaultForWrite(void* data, size_t bytes) {
#ifdef MADV_POPULATE_WRITE
  static const size_t kPage = static_cast<size_t>(::sysconf(_SC_PAGESIZE));
  // Below a few pages the call costs more than the faults it saves.
  if (bytes < 16 * kPage) return;
  const uintptr_t begin = (reinterpret_cast<uintptr_t>(data) + kPage - 1) / kPage * kPage;
  const uintptr_t end = (reinterpret_cast<uintptr_t>(data) + bytes) / kPage * kPage;
  if (end > begin) ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
  (void)data;
  (void)bytes;
#endif
}

void ReserveMappedHeap(size_t bytes) {
#if defined(MADV_POPULATE_WRITE) && !defined(__SANITIZE_ADDRESS__)
  if (::mallopt(M_TOP_PAD, static_cast<int>(bytes)) == 0) return;
  // Blocks below the mmap threshold come from the top of the heap until it runs out; the
  // next one grows the heap by itself plus the pad. Freed, they rejoin the top.
  constexpr size_t kBlock = size_t{64} << 10;
  const void* const before = ::sbrk(0);
  void* blocks[16];
  size_t taken = 0;
  while (taken < std::size(blocks) && ::sbrk(0) == before) {
    blocks[taken] = std::malloc(kBlock);
    if (blocks[taken] == nullptr) break;
    ++taken;
  }
  for (size_t i = 0; i < taken; ++i) std::free(blocks[i]);
  // The whole heap, from its start: pages already in use cost the call next to nothing.
  const uintptr_t top = reinterpret_cast<uintptr_t>(::sbrk(0));
  const size_t heap = ::mallinfo2().arena;
  if (heap > 0 && heap <= top) PrefaultForWrite(reinterpret_cast<void*>(top - heap), heap);
#else
  (void)bytes;
#endif
}

void LargeBuffer::resize(size_t bytes) {
  if (bytes <= capacity_ && data_ != nullptr) {
    size_ = bytes;
    return;
  }
  LargeBuffer larger(bytes);
  if (size_ > 0) std::memcpy(larger.data_, data_, size_);
  *this = std::move(larger);
}

}  // namespace mocapfill
