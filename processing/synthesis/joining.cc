#include "processing/synthesis/joining.h"

#include <algorithm>
#include <limits>
#include <map>

namespace mocapfill {

namespace {

// Seam cost between candidate fragments a (before) and b (after).
double Transition(const JoinInputs& in, const DbFragment& a, const DbFragment& b) {
  if (Continues(a, b)) return 0.0;
  const Eigen::MatrixXf& s = in.db->signals();
  const ClipRange& ca = in.db->clip(a.clip);
  const ClipRange& cb = in.db->clip(b.clip);
  const int ea = ca.first_frame + a.last, sb = cb.first_frame + b.first;
  const int ea0 = ca.first_frame + std::max(0, a.last - 1);
  const int sb1 = cb.first_frame + std::min(cb.num_frames - 1, b.first + 1);
  double cost = 0.0;
  for (int c : in.target_channels) {
    const double sigma2 = double(in.channel_sigma[c]) * in.channel_sigma[c];
    const double jump = s(ea, c) - s(sb, c);
    const double slope = (s(ea, c) - s(ea0, c)) - (s(sb1, c) - s(sb, c));
    cost += (jump * jump + in.gamma * slope * slope) / sigma2;
  }
  return in.target_channels.empty() ? 0.0 : cost / in.target_channels.size();
}

std::vector<int> Greedy(const JoinInputs& in) { return std::vector<int>(in.candidates->size(), 0); }

std::vector<int> Viterbi(const JoinInputs& in) {
  const auto& cands = *in.candidates;
  const size_t n = cands.size();
  std::vector<int> path(n, 0);
  if (n == 0) return path;
  std::vector<std::vector<double>> cost(n);
  std::vector<std::vector<int>> back(n);
  cost[0].resize(cands[0].size());
  for (size_t c = 0; c < cands[0].size(); ++c) cost[0][c] = cands[0][c].distance;
  const auto& frags = in.mdb->fragments();
  for (size_t i = 1; i < n; ++i) {
    cost[i].assign(cands[i].size(), std::numeric_limits<double>::infinity());
    back[i].assign(cands[i].size(), 0);
    for (size_t c = 0; c < cands[i].size(); ++c) {
      const DbFragment& to = frags[cands[i][c].fragment];
      for (size_t p = 0; p < cands[i - 1].size(); ++p) {
        const double v = cost[i - 1][p] + Transition(in, frags[cands[i - 1][p].fragment], to);
        if (v < cost[i][c]) {
          cost[i][c] = v;
          back[i][c] = static_cast<int>(p);
        }
      }
      cost[i][c] += cands[i][c].distance;
    }
  }
  const auto last = std::min_element(cost[n - 1].begin(), cost[n - 1].end());
  path[n - 1] = static_cast<int>(last - cost[n - 1].begin());
  for (size_t i = n - 1; i > 0; --i) path[i - 1] = back[i][path[i]];
  return path;
}

// Thesis "best animation" [R]: the clip whose candidates explain the sketch best takes every
// fragment where it has a candidate; the cost-matrix path fills the rest.
std::vector<int> BestAnimation(const JoinInputs& in) {
  const auto& cands = *in.candidates;
  const auto& frags = in.mdb->fragments();
  std::vector<int> path = Viterbi(in);
  std::map<int, std::vector<double>> best_by_clip;  // clip -> best distance per fragment (-1 none)
  std::vector<double> penalty(cands.size(), 0.0);
  for (size_t i = 0; i < cands.size(); ++i) {
    std::vector<double> d;
    for (const Candidate& c : cands[i]) d.push_back(c.distance);
    if (!d.empty()) {
      std::nth_element(d.begin(), d.begin() + d.size() / 2, d.end());
      penalty[i] = 2.0 * d[d.size() / 2];
    }
    for (const Candidate& c : cands[i]) {
      auto& v = best_by_clip.try_emplace(frags[c.fragment].clip, cands.size(), -1.0).first->second;
      if (v[i] < 0.0 || c.distance < v[i]) v[i] = c.distance;
    }
  }
  int best_clip = -1;
  double best_score = std::numeric_limits<double>::infinity();
  for (const auto& [clip, v] : best_by_clip) {
    double score = 0.0;
    for (size_t i = 0; i < v.size(); ++i) score += v[i] >= 0.0 ? v[i] : penalty[i];
    if (score < best_score) {
      best_score = score;
      best_clip = clip;
    }
  }
  for (size_t i = 0; i < cands.size(); ++i)
    for (size_t c = 0; c < cands[i].size(); ++c)
      if (frags[cands[i][c].fragment].clip == best_clip) {
        path[i] = static_cast<int>(c);  // ascending order: the first hit is that clip's best
        break;
      }
  return path;
}

}  // namespace

bool Continues(const DbFragment& a, const DbFragment& b) {
  return a.clip == b.clip && std::abs(b.first - a.last) <= 1;
}

std::vector<int> JoinCandidates(JoinCriterion criterion, const JoinInputs& in) {
  switch (criterion) {
    case JoinCriterion::kBestFragment: return Greedy(in);
    case JoinCriterion::kCostMatrix: return Viterbi(in);
    case JoinCriterion::kBestAnimation: return BestAnimation(in);
  }
  return Greedy(in);
}

}  // namespace mocapfill
