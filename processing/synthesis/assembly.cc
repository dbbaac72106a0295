#include "processing/synthesis/assembly.h"

#include <algorithm>
#include <cmath>

#include "processing/core/smoothstep.h"

namespace mocapfill {

// The candidates blended into one fragment: the nearest `blend`, with the lead replacing the
// farthest when it is not among them.
std::vector<int> BlendSet(const std::vector<Candidate>& cands, int lead, int blend) {
  std::vector<int> set;
  for (int c = 0; c < std::min<int>(blend, static_cast<int>(cands.size())); ++c) set.push_back(c);
  if (std::find(set.begin(), set.end(), lead) == set.end()) {
    if (set.empty()) set.push_back(lead); else set.back() = lead;
  }
  return set;
}

std::vector<double> DistanceWeights(const std::vector<Candidate>& cands, const std::vector<int>& set) {
  double mean_d = 0.0;
  for (int c : set) mean_d += cands[c].distance;
  mean_d = std::max(1e-9, mean_d / set.size());
  std::vector<double> w;
  double total = 0.0;
  for (int c : set) total += w.emplace_back(std::exp(-cands[c].distance / mean_d));
  for (double& x : w) x /= total;
  return w;
}

namespace {

// Cross-fade weight of sketch frame t for fragment f extended by `margin` frames per side:
// 1 inside the fragment, falling to 0 just beyond the margin along a smoothstep. A linear ramp
// has a kink at each end, and the blend of two takes turns it into a jolt of the synthesised
// joints wherever a fragment starts or stops counting.
double FadeWeight(const SketchFragment& f, int margin, int t) {
  const int outside = t < f.first ? f.first - t : t > f.last ? t - f.last : 0;
  return Smoothstep(1.0 - double(outside) / (margin + 1));
}

// Adds weight * fade(t) * (the candidate's rows of `s`, columns `channels`, stretched onto
// sketch frames [from, to)) to acc (frames x channels.size()), and weight * fade(t) to weights.
void AddStretched(const MotionDatabase& db, const Eigen::MatrixXf& s, const DbFragment& g, const SketchFragment& f,
                  int from, int to, int margin, const std::vector<int>& channels, double weight, Eigen::MatrixXd& acc,
                  Eigen::VectorXd& weights) {
  const ClipRange& clip = db.clip(g.clip);
  const int span = std::max(1, f.last - f.first);
  for (int t = from; t < to; ++t) {
    const double u = g.first + double(t - f.first) * (g.last - g.first) / span;
    const double uc = std::clamp(u, 0.0, double(clip.num_frames - 1));
    const int a = static_cast<int>(uc), b = std::min(a + 1, clip.num_frames - 1);
    const double w = uc - a, fw = weight * FadeWeight(f, margin, t);
    for (size_t i = 0; i < channels.size(); ++i) {
      const int c = channels[i];
      acc(t, i) += fw * ((1.0 - w) * s(clip.first_frame + a, c) + w * s(clip.first_frame + b, c));
    }
    weights[t] += fw;
  }
}

}  // namespace

std::vector<int> AssembleFragments(const AssemblyInputs& in, Eigen::MatrixXd& out) {
  const auto& frags = *in.fragments;
  const int rows = static_cast<int>(out.rows());
  std::vector<int> blended(frags.size(), 0);
  Eigen::MatrixXd acc = Eigen::MatrixXd::Zero(rows, in.channels.size());
  Eigen::VectorXd weights = Eigen::VectorXd::Zero(rows);
  for (size_t i = 0; i < frags.size(); ++i) {
    const std::vector<Candidate>& cands = (*in.candidates)[i];
    if (cands.empty()) continue;
    const int margin = static_cast<int>(std::lround(in.crossfade * (frags[i].last - frags[i].first)));
    // Without cross-fading fragments own [first, last) (the last one its end frame too).
    const int from = std::max(0, frags[i].first - margin);
    const int to = margin > 0 ? std::min(rows, frags[i].last + margin + 1)
                              : (i + 1 == frags.size() ? frags[i].last + 1 : frags[i].last);
    const std::vector<int> set = BlendSet(cands, in.leads[i], in.blend);
    const std::vector<double> w = in.weights ? (*in.weights)[i] : DistanceWeights(cands, set);
    const Eigen::MatrixXf& source = in.source ? *in.source : in.db->signals();
    for (size_t k = 0; k < set.size(); ++k)
      AddStretched(*in.db, source, in.mdb->fragments()[cands[set[k]].fragment], frags[i], from, to, margin,
                   in.channels, w[k], acc, weights);
    blended[i] = static_cast<int>(set.size());
  }
  for (int t = 0; t < rows; ++t)
    if (weights[t] > 0.0)
      for (size_t i = 0; i < in.channels.size(); ++i) out(t, in.channels[i]) = acc(t, i) / weights[t];
  return blended;
}

void SmoothSeams(Eigen::MatrixXd& out, const std::vector<int>& channels, const std::vector<SketchFragment>& fragments,
                 int window_frames) {
  const int rows = static_cast<int>(out.rows());
  for (size_t i = 1; i < fragments.size(); ++i) {
    const int b = fragments[i].first;
    if (b < 2 || b + 1 >= rows) continue;
    const int left_len = fragments[i - 1].last - fragments[i - 1].first;
    const int right_len = fragments[i].last - fragments[i].first;
    const int s = std::min({window_frames, std::max(1, left_len / 2), std::max(1, right_len / 2)});
    if (s < 1) continue;
    for (int c : channels) {
      const double expected = ((out(b - 1, c) - out(b - 2, c)) + (out(b + 1, c) - out(b, c))) / 2.0;
      const double jump = (out(b, c) - out(b - 1, c)) - expected;
      for (int d = 0; d < s; ++d) {
        const double fall = (1.0 - double(d) / s) * (1.0 - double(d) / s);
        if (b - 1 - d >= 0) out(b - 1 - d, c) += 0.5 * jump * fall;
        if (b + d < rows) out(b + d, c) -= 0.5 * jump * fall;
      }
    }
  }
}

}  // namespace mocapfill
