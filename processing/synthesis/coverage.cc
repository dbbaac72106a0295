#include "processing/synthesis/coverage.h"

#include <algorithm>
#include <cmath>

#include "processing/core/median.h"
#include "processing/core/smoothstep.h"

namespace mocapfill {

namespace {

// 0 below `from`, 1 from `to` on, smoothstep in between.
double Ramp(double share, double from, double to) { return Smoothstep((share - from) / (to - from)); }

}  // namespace

double ReferenceDistance(const MatchingDatabase& mdb, const std::vector<DrivenChannel>& driven,
                         const FragmentFillOptions& options) {
  const int n = static_cast<int>(mdb.fragments().size());
  if (n == 0 || driven.empty()) return 0.0;
  const int stride = std::max(1, (n + options.coverage.reference_fragments - 1) / options.coverage.reference_fragments);
  std::vector<int> queries;
  for (int i = stride / 2; i < n; i += stride) queries.push_back(i);
  std::vector<float> nearest = NearestOtherTakeDistances(mdb, queries, driven, options);
  nearest.erase(std::remove_if(nearest.begin(), nearest.end(), [](float d) { return !std::isfinite(d); }),
                nearest.end());
  if (nearest.empty()) return 0.0;
  return std::sqrt(UpperMedian(std::move(nearest)));
}

CoverageReport MeasureCoverage(const std::vector<SketchFragment>& fragments,
                               const std::vector<std::vector<Candidate>>& nearest, const std::vector<float>& energies,
                               double reference, const CoverageOptions& options) {
  CoverageReport report;
  report.measured = true;
  report.reference_distance = reference;
  report.poor_share = options.poor_share;
  report.none_share = options.none_share;
  report.texture_poor_share = options.texture_poor_share;
  report.texture_none_share = options.texture_none_share;
  if (options.blend) report.prior = options.prior == CoveragePrior::kMean ? "mean" : "nn";
  for (size_t f = 0; f < fragments.size(); ++f) {
    FragmentCoverage c;
    c.first_frame = fragments[f].first;
    c.last_frame = fragments[f].last;
    c.distance = nearest[f].empty() ? 0.0 : nearest[f].front().distance;
    // A fragment standing at the mean pose has nothing to explain: any miss counts in full.
    c.unexplained = c.distance / std::max<double>(energies[f], 1e-9);
    if (reference > 0.0) c.takes_ratio = std::sqrt(c.distance) / reference;
    if (options.blend) {
      c.prior_weight = Ramp(c.unexplained, options.poor_share, options.none_share);
      c.texture_weight = Ramp(c.unexplained, options.texture_poor_share, options.texture_none_share);
    }
    report.fragments.push_back(c);
    if (c.unexplained < options.poor_share) continue;
    const bool extends = f > 0 && !report.poor.empty() && report.fragments[f - 1].unexplained >= options.poor_share;
    if (!extends) report.poor.push_back({c.first_frame, c.last_frame});
    PoorlyCoveredStretch& stretch = report.poor.back();
    stretch.last_frame = c.last_frame;
    stretch.worst_unexplained = std::max(stretch.worst_unexplained, c.unexplained);
    stretch.worst_takes_ratio = std::max(stretch.worst_takes_ratio, c.takes_ratio);
    stretch.max_prior_weight = std::max(stretch.max_prior_weight, c.prior_weight);
  }
  return report;
}

double MedianUnexplained(const CoverageReport& coverage) {
  std::vector<double> shares;
  for (const FragmentCoverage& f : coverage.fragments) shares.push_back(f.unexplained);
  if (shares.empty()) return 0.0;
  return UpperMedian(std::move(shares));
}

Eigen::VectorXd WeightPerFrame(const CoverageReport& coverage, double FragmentCoverage::*of, int frames) {
  Eigen::VectorXd weight = Eigen::VectorXd::Zero(frames);
  const std::vector<FragmentCoverage>& f = coverage.fragments;
  if (f.empty() || frames == 0) return weight;
  const auto middle = [&](size_t i) { return 0.5 * (f[i].first_frame + f[i].last_frame); };
  size_t next = 0;
  for (int frame = 0; frame < frames; ++frame) {
    while (next < f.size() && middle(next) < frame) ++next;
    if (next == 0) {
      weight[frame] = f.front().*of;
    } else if (next == f.size()) {
      weight[frame] = f.back().*of;
    } else {
      const double a = middle(next - 1), b = middle(next);
      const double t = b > a ? (frame - a) / (b - a) : 1.0;
      weight[frame] = (1.0 - t) * (f[next - 1].*of) + t * (f[next].*of);
    }
  }
  return weight;
}

void BlendTowards(const Eigen::MatrixXd& prior, const Eigen::VectorXd& weight, const std::vector<int>& channels,
                  Eigen::MatrixXd& out) {
  for (int c : channels)
    out.col(c) = (1.0 - weight.array()) * out.col(c).array() + weight.array() * prior.col(c).array();
}

}  // namespace mocapfill
