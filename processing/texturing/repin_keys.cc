#include "processing/texturing/repin_keys.h"

#include <algorithm>

namespace mocapfill {

void RepinKeys(const Eigen::MatrixXd& keyed, const std::vector<std::vector<int>>& key_frames,
               const std::vector<int>& channels, Eigen::MatrixXd& out) {
  const int rows = static_cast<int>(out.rows());
  for (int c : channels) {
    const std::vector<int>& keys = key_frames[c];
    if (keys.empty()) continue;
    std::vector<double> d(keys.size());
    for (size_t k = 0; k < keys.size(); ++k) d[k] = out(keys[k], c) - keyed(keys[k], c);
    // Catmull-Rom slopes through (key, offset) pairs, one-sided at the ends.
    std::vector<double> m(keys.size(), 0.0);
    for (size_t k = 0; k < keys.size(); ++k) {
      const size_t lo = k == 0 ? 0 : k - 1, hi = std::min(keys.size() - 1, k + 1);
      if (hi > lo) m[k] = (d[hi] - d[lo]) / (keys[hi] - keys[lo]);
    }
    for (int f = 0; f < rows; ++f) {
      double offset;
      if (f <= keys.front()) {
        offset = d.front();
      } else if (f >= keys.back()) {
        offset = d.back();
      } else {
        const size_t k = std::upper_bound(keys.begin(), keys.end(), f) - keys.begin() - 1;
        const double h = keys[k + 1] - keys[k], u = (f - keys[k]) / h;
        const double h00 = 2 * u * u * u - 3 * u * u + 1, h10 = u * u * u - 2 * u * u + u;
        const double h01 = -2 * u * u * u + 3 * u * u, h11 = u * u * u - u * u;
        offset = h00 * d[k] + h10 * h * m[k] + h01 * d[k + 1] + h11 * h * m[k + 1];
      }
      out(f, c) -= offset;
    }
  }
}

}  // namespace mocapfill
