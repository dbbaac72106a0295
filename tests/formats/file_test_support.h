// Inputs for the whole-file readers' tests (file_io_test.cc, fast_convert/file_text_test.cc):
// a byte pattern of any length that differs from page to page, and a fifo fed from a thread.
#pragma once

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cstddef>
#include <fstream>
#include <string>
#include <thread>

namespace mocapfill::testing {

inline std::string Pattern(size_t bytes) {
  std::string s(bytes, '\0');
  for (size_t i = 0; i < bytes; ++i) s[i] = static_cast<char>('a' + (i * 7 + i / 4093) % 26);
  return s;
}

// A fifo at `fifo`, and a thread that writes `bytes` into it once a reader opens it.
inline std::thread FeedFifo(const std::string& fifo, const std::string& bytes) {
  EXPECT_EQ(::mkfifo(fifo.c_str(), 0600), 0) << fifo;
  return std::thread([fifo, &bytes] {
    std::ofstream out(fifo, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

}  // namespace mocapfill::testing
