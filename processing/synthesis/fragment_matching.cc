#include "processing/synthesis/fragment_matching.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <thread>

#include "processing/analysis/phases.h"

namespace mocapfill {

namespace {

// Query rows (fragments x features) and the database columns they use, both scaled so that
// a squared Euclidean distance is the weighted, normalised matching distance.
struct ScaledProblem {
  Eigen::MatrixXf queries;
  Eigen::MatrixXf database;
};

ScaledProblem Scale(const MatchingDatabase& mdb, const Eigen::MatrixXd& sketch_match,
                    const std::vector<SketchFragment>& fragments, const std::vector<DrivenChannel>& driven,
                    const FillOptions& options) {
  const int samples = mdb.samples(), channels = static_cast<int>(mdb.channel_sigma().size());
  const int nd = static_cast<int>(driven.size());
  double total_weight = 0.0;
  for (const DrivenChannel& d : driven) total_weight += d.weight;
  Eigen::VectorXf scale(nd);
  std::vector<int> columns(nd);
  for (int i = 0; i < nd; ++i) {
    columns[i] = driven[i].channel;
    const double sigma = mdb.channel_sigma()[driven[i].channel];
    scale[i] = static_cast<float>(std::sqrt(driven[i].weight / (total_weight * samples)) / sigma);
  }
  ScaledProblem p;
  const Eigen::MatrixXf sketch_f = sketch_match.cast<float>();
  p.queries.resize(static_cast<Eigen::Index>(fragments.size()), samples * nd);
  std::vector<float> row(samples * nd);
  for (size_t f = 0; f < fragments.size(); ++f) {
    double wa, wb;
    MatchingWindow(fragments[f].first, fragments[f].last, options.context_fraction, wa, wb);
    SampleWindow(sketch_f, wa, wb, samples, columns, row.data());
    for (int s = 0; s < samples; ++s)
      for (int i = 0; i < nd; ++i) p.queries(f, s * nd + i) = row[s * nd + i] * scale[i];
  }
  const Eigen::MatrixXf& all = mdb.features();
  p.database.resize(all.rows(), samples * nd);
  for (int s = 0; s < samples; ++s)
    for (int i = 0; i < nd; ++i) p.database.col(s * nd + i) = all.col(s * channels + columns[i]) * scale[i];
  return p;
}

bool Admissible(const SketchFragment& query, const DbFragment& db, const FillOptions& options) {
  if (query.rising != db.rising) return false;
  const double ratio = double(std::max(1, db.last - db.first)) / std::max(1, query.last - query.first);
  return ratio >= options.min_length_ratio && ratio <= options.max_length_ratio;
}

std::vector<Candidate> Best(std::vector<Candidate> all, int k) {
  const auto less = [](const Candidate& a, const Candidate& b) {
    return a.distance < b.distance || (a.distance == b.distance && a.fragment < b.fragment);
  };
  const size_t keep = std::min<size_t>(k, all.size());
  std::partial_sort(all.begin(), all.begin() + keep, all.end(), less);
  all.resize(keep);
  return all;
}

}  // namespace

Result<std::vector<SketchFragment>> FragmentSketch(const SketchSignals& sketch, int master_channel, int band,
                                                   double rate_hz) {
  const Eigen::VectorXd signal = BandOf(sketch.values.col(master_channel), rate_hz, band);
  ASSIGN_OR_RETURN(std::vector<Phase> phases, FindPhases(signal, rate_hz));
  std::vector<SketchFragment> fragments;
  for (const Phase& p : phases) fragments.push_back({p.first, p.last, p.rising});
  if (fragments.empty()) fragments.push_back({0, std::max(0, sketch.frames - 1), true});
  return fragments;
}

int ChooseMasterChannel(const SketchSignals& sketch, int band, double rate_hz) {
  int best = -1;
  double best_energy = -1.0;
  for (int c = 0; c < 3 * sketch.num_joints; ++c) {
    if (!sketch.keyed[c]) continue;
    const double energy = BandOf(sketch.values.col(c), rate_hz, band).squaredNorm();
    if (energy > best_energy) {
      best_energy = energy;
      best = c;
    }
  }
  if (best < 0)  // only root features keyed: fragment on the first of them
    for (int c = 0; c < sketch.num_channels() && best < 0; ++c)
      if (sketch.keyed[c]) best = c;
  return best;
}

std::vector<std::vector<Candidate>> MatchFragments(const MatchingDatabase& mdb, const Eigen::MatrixXd& sketch_match,
                                                   const std::vector<SketchFragment>& fragments,
                                                   const std::vector<DrivenChannel>& driven,
                                                   const FillOptions& options) {
  const ScaledProblem p = Scale(mdb, sketch_match, fragments, driven, options);
  const Eigen::VectorXf db_norms = p.database.rowwise().squaredNorm();
  const Eigen::VectorXf query_norms = p.queries.rowwise().squaredNorm();
  const int nf = static_cast<int>(fragments.size());
  std::vector<std::vector<Candidate>> result(nf);
  auto work = [&](int f) {
    const Eigen::VectorXf dots = p.database * p.queries.row(f).transpose();
    std::vector<Candidate> admissible, any;
    admissible.reserve(mdb.fragments().size());
    for (Eigen::Index r = 0; r < dots.size(); ++r) {
      const float d = std::max(0.0f, query_norms[f] + db_norms[r] - 2.0f * dots[r]);
      const Candidate c{static_cast<int>(r), d};
      if (Admissible(fragments[f], mdb.fragments()[r], options)) {
        admissible.push_back(c);
      } else if (admissible.empty()) {
        any.push_back(c);
      }
    }
    result[f] = Best(admissible.empty() ? std::move(any) : std::move(admissible), options.candidates);
  };
  const int workers = std::max(1, options.threads > 0 ? options.threads : int(std::thread::hardware_concurrency()));
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w)
    threads.emplace_back([&, w] {
      for (int f = w; f < nf; f += workers) work(f);
    });
  for (std::thread& t : threads) t.join();
  return result;
}

}  // namespace mocapfill
