#include "processing/evaluation/bootstrap.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

namespace mocapfill {

namespace {

double MeanOf(const std::vector<double>& values) {
  double sum = 0.0;
  for (double v : values) sum += v;
  return values.empty() ? 0.0 : sum / values.size();
}

// Percentile p in [0, 1] of sorted values, linear between neighbouring order statistics.
double SortedPercentile(const std::vector<double>& sorted, double p) {
  const double at = p * (sorted.size() - 1);
  const size_t below = static_cast<size_t>(std::floor(at));
  const size_t above = std::min(below + 1, sorted.size() - 1);
  return sorted[below] + (at - below) * (sorted[above] - sorted[below]);
}

Interval PercentileInterval(std::vector<double> statistics, double level) {
  if (statistics.empty()) return {};
  std::sort(statistics.begin(), statistics.end());
  return {SortedPercentile(statistics, (1.0 - level) / 2.0), SortedPercentile(statistics, (1.0 + level) / 2.0)};
}

// Draws of indices into n items, the same sequence for the same seed, n and groups. Without
// groups each draw picks n items; with groups it picks as many groups as there are, and for
// each picked group as many of its items as it has.
template <typename Statistic>
std::vector<double> Resample(size_t n, const BootstrapGroups& groups, const BootstrapOptions& options,
                             Statistic statistic) {
  std::vector<std::vector<size_t>> members;
  if (groups.size() == n) {
    std::map<int, size_t> slot;
    for (size_t i = 0; i < n; ++i) {
      const auto [it, fresh] = slot.emplace(groups[i], members.size());
      if (fresh) members.emplace_back();
      members[it->second].push_back(i);
    }
  } else {
    for (size_t i = 0; i < n; ++i) members.push_back({i});
  }
  std::mt19937_64 random(options.seed);
  std::uniform_int_distribution<size_t> pick_group(0, members.size() - 1);
  std::vector<size_t> draw;
  std::vector<double> out;
  out.reserve(std::max(0, options.resamples));
  for (int r = 0; r < options.resamples; ++r) {
    draw.clear();
    for (size_t g = 0; g < members.size(); ++g) {
      const std::vector<size_t>& group = members[pick_group(random)];
      if (group.size() == 1) {
        draw.push_back(group.front());
        continue;
      }
      std::uniform_int_distribution<size_t> pick_member(0, group.size() - 1);
      for (size_t k = 0; k < group.size(); ++k) draw.push_back(group[pick_member(random)]);
    }
    out.push_back(statistic(draw));
  }
  return out;
}

}  // namespace

Interval BootstrapMean(const std::vector<double>& values, const BootstrapOptions& options,
                       const BootstrapGroups& groups) {
  if (values.empty()) return {};
  return PercentileInterval(Resample(values.size(), groups, options,
                                     [&](const std::vector<size_t>& draw) {
                                       double sum = 0.0;
                                       for (size_t i : draw) sum += values[i];
                                       return sum / draw.size();
                                     }),
                            options.level);
}

Interval BootstrapWeightedMean(const std::vector<double>& values, const std::vector<double>& weights,
                               const BootstrapOptions& options, const BootstrapGroups& groups) {
  if (values.empty() || values.size() != weights.size()) return {};
  return PercentileInterval(Resample(values.size(), groups, options,
                                     [&](const std::vector<size_t>& draw) {
                                       double sum = 0.0, total = 0.0;
                                       for (size_t i : draw) {
                                         sum += weights[i] * values[i];
                                         total += weights[i];
                                       }
                                       return total > 0.0 ? sum / total : 0.0;
                                     }),
                            options.level);
}

RelativeDifference BootstrapPercentBelow(const std::vector<double>& values, const std::vector<double>& reference,
                                         const BootstrapOptions& options, const BootstrapGroups& groups) {
  const double ref = MeanOf(reference);
  if (values.empty() || values.size() != reference.size() || ref == 0.0) return {};
  RelativeDifference out;
  out.percent = 100.0 * (ref - MeanOf(values)) / ref;
  // A draw whose reference mean is zero has no relative difference; it counts as no change.
  out.interval = PercentileInterval(Resample(values.size(), groups, options,
                                             [&](const std::vector<size_t>& draw) {
                                               double v = 0.0, r = 0.0;
                                               for (size_t i : draw) {
                                                 v += values[i];
                                                 r += reference[i];
                                               }
                                               return r == 0.0 ? 0.0 : 100.0 * (r - v) / r;
                                             }),
                                    options.level);
  return out;
}

}  // namespace mocapfill
