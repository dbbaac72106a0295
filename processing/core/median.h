// The median the fill's statistics use (key spacings, standing heights, match distances):
// robust to the few outliers (a held key, a stumble, a bad match) a mean would follow.
#pragma once

#include <algorithm>
#include <vector>

namespace mocapfill {

// The upper median of `values` (the element at size / 2 once sorted), in linear time.
// `values` must not be empty.
template <typename T>
T UpperMedian(std::vector<T> values) {
  const auto middle = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace mocapfill
