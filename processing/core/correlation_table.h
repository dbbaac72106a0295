// The joint-correlation table as data (algorithms.md 4a.1): for every channel pair (a, b) of
// a band-pass signal, the correlation of a with b shifted by the lag that maximises |corr|.
//
// It lives in core because the .mfdb file format (formats/mfdb) stores the database's table
// and formats may depend only on core. Computing it is an algorithm:
// processing/analysis/correlation.h.
#pragma once

#include <cstddef>
#include <vector>

namespace mocapfill {

struct CorrelationEntry {
  float max_abs = 0.0f;  // max over lags of |corr|, in [0, 1]
  float value = 0.0f;    // the signed correlation at that lag
  int lag_frames = 0;    // tau: corr(a[t], b[t + tau]); tau > 0 means b follows a
};

struct CorrelationTable {
  int num_channels = 0;
  int max_lag_frames = 0;
  int band = -1;            // Laplacian band the table was computed on (-1: raw signals)
  double rate_hz = 0.0;     // sample rate of the signals (lag_frames / rate_hz = seconds)
  std::vector<CorrelationEntry> entries;  // row-major, num_channels x num_channels

  const CorrelationEntry& at(int a, int b) const { return entries[static_cast<size_t>(a) * num_channels + b]; }
  bool empty() const { return entries.empty(); }
};

}  // namespace mocapfill
