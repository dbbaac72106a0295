// Streaming XXH64 (Yann Collet's xxHash, 64-bit variant, seed 0 by default): the .mfdb
// checksum. Fast enough (several GB/s) that verifying a whole database costs a few ms.
#pragma once

#include <cstddef>
#include <cstdint>

namespace mocapfill {

class Xxh64 {
 public:
  explicit Xxh64(std::uint64_t seed = 0);
  void Update(const void* data, size_t size);
  std::uint64_t Digest() const;

 private:
  std::uint64_t v_[4];
  std::uint64_t seed_;
  std::uint64_t total_ = 0;
  unsigned char buffer_[32];
  size_t buffered_ = 0;
};

}  // namespace mocapfill
