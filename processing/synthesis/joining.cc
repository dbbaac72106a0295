#include "processing/synthesis/joining.h"

#include "processing/core/median.h"

#include <algorithm>
#include <limits>
#include <map>

namespace mocapfill {

namespace {

// The target channels at both ends of a candidate, normalised by their spread: values and
// one-frame slopes, so a seam cost is a few vector operations.
struct Ends {
  Eigen::VectorXd start, start_slope, end, end_slope;
};

Ends CandidateEnds(const JoinInputs& in, const DbFragment& g) {
  const Eigen::MatrixXf& s = in.db->signals();
  const ClipRange& clip = in.db->clip(g.clip);
  const int first = clip.first_frame + g.first, last = clip.first_frame + g.last;
  const int before_last = clip.first_frame + std::max(0, g.last - 1);
  const int after_first = clip.first_frame + std::min(clip.num_frames - 1, g.first + 1);
  const int n = static_cast<int>(in.target_channels.size());
  Ends e{Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n), Eigen::VectorXd(n)};
  for (int i = 0; i < n; ++i) {
    const int c = in.target_channels[i];
    const double inv = 1.0 / in.channel_sigma[c];
    e.start[i] = s(first, c) * inv;
    e.start_slope[i] = (s(after_first, c) - s(first, c)) * inv;
    e.end[i] = s(last, c) * inv;
    e.end_slope[i] = (s(last, c) - s(before_last, c)) * inv;
  }
  return e;
}

// Seam cost between candidate fragments a (before) and b (after): mean over target channels of
// the normalised jump plus gamma times the normalised slope change.
double Transition(const JoinInputs& in, const DbFragment& a, const Ends& ea, const DbFragment& b, const Ends& eb) {
  if (Continues(a, b) || in.target_channels.empty()) return 0.0;
  const double jump = (ea.end - eb.start).squaredNorm();
  const double slope = (ea.end_slope - eb.start_slope).squaredNorm();
  return (jump + in.gamma * slope) / in.target_channels.size();
}

std::vector<int> Greedy(const JoinInputs& in) { return std::vector<int>(in.candidates->size(), 0); }

std::vector<int> Viterbi(const JoinInputs& in) {
  const auto& cands = *in.candidates;
  const size_t n = cands.size();
  std::vector<int> path(n, 0);
  for (const std::vector<Candidate>& c : cands)
    if (c.empty()) return path;  // a fragment without candidates: nothing to choose anywhere
  std::vector<std::vector<double>> cost(n);
  std::vector<std::vector<int>> back(n);
  cost[0].resize(cands[0].size());
  for (size_t c = 0; c < cands[0].size(); ++c) cost[0][c] = cands[0][c].distance;
  const auto& frags = in.mdb->fragments();
  std::vector<std::vector<Ends>> ends(n);
  for (size_t i = 0; i < n; ++i)
    for (const Candidate& c : cands[i]) ends[i].push_back(CandidateEnds(in, frags[c.fragment]));
  for (size_t i = 1; i < n; ++i) {
    cost[i].assign(cands[i].size(), std::numeric_limits<double>::infinity());
    back[i].assign(cands[i].size(), 0);
    for (size_t c = 0; c < cands[i].size(); ++c) {
      const DbFragment& to = frags[cands[i][c].fragment];
      for (size_t p = 0; p < cands[i - 1].size(); ++p) {
        const double v = cost[i - 1][p] + Transition(in, frags[cands[i - 1][p].fragment], ends[i - 1][p], to,
                                                     ends[i][c]);
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

// Thesis "best animation" (the thesis names the criterion only; this is a reconstruction): the clip whose candidates explain the sketch best takes every
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
    if (!d.empty()) penalty[i] = 2.0 * UpperMedian(std::move(d));
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
