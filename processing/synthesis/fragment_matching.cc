#include "processing/synthesis/fragment_matching.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <thread>

#include "processing/analysis/phases.h"
#include "processing/core/signal_layout.h"

namespace mocapfill {

namespace {

// Per driven channel: its column among the matching channels and the factor that makes a
// squared Euclidean distance the weighted, normalised matching distance.
struct Scaling {
  std::vector<int> columns;
  Eigen::VectorXf factor;
};

Scaling ScalingOf(const MatchingDatabase& mdb, const std::vector<DrivenChannel>& driven) {
  const int nd = static_cast<int>(driven.size());
  double total_weight = 0.0;
  for (const DrivenChannel& d : driven) total_weight += d.weight;
  Scaling scaling{std::vector<int>(nd), Eigen::VectorXf(nd)};
  for (int i = 0; i < nd; ++i) {
    scaling.columns[i] = driven[i].channel;
    const double sigma = mdb.channel_sigma()[driven[i].channel];
    scaling.factor[i] = static_cast<float>(std::sqrt(driven[i].weight / (total_weight * mdb.samples())) / sigma);
  }
  return scaling;
}

// The columns of a scaled row (sample-major, as ScaledDatabase lays them out) that hold the
// root's velocities, which a time-stretch scales; none unless options.stretched_travel.
std::vector<int> VelocityColumns(const MatchingDatabase& mdb, const Scaling& scaling,
                                 const FragmentFillOptions& options) {
  if (!options.stretched_travel) return {};
  const int first_feature = static_cast<int>(mdb.channel_sigma().size()) - kNumRootFeatures;
  const int nd = static_cast<int>(scaling.columns.size());
  std::vector<int> columns;
  for (int s = 0; s < mdb.samples(); ++s)
    for (int i = 0; i < nd; ++i)
      if (scaling.columns[i] >= first_feature && IsRootVelocityFeature(scaling.columns[i] - first_feature))
        columns.push_back(s * nd + i);
  return columns;
}

// The scaled features of the listed database fragments, or of all of them (rows null).
Eigen::MatrixXf ScaledDatabase(const MatchingDatabase& mdb, const Scaling& scaling,
                               const std::vector<int>* rows = nullptr) {
  const int samples = mdb.samples(), channels = static_cast<int>(mdb.channel_sigma().size());
  const int nd = static_cast<int>(scaling.columns.size());
  const Eigen::MatrixXf& all = mdb.features();
  const Eigen::Index n = rows ? static_cast<Eigen::Index>(rows->size()) : all.rows();
  Eigen::MatrixXf database(n, samples * nd);
  for (Eigen::Index r = 0; r < n; ++r) {
    const Eigen::Index from = rows ? (*rows)[r] : r;
    for (int s = 0; s < samples; ++s)
      for (int i = 0; i < nd; ++i)
        database(r, s * nd + i) = all(from, s * channels + scaling.columns[i]) * scaling.factor[i];
  }
  return database;
}

Eigen::MatrixXf ScaledQueries(const MatchingDatabase& mdb, const Eigen::MatrixXd& sketch_match,
                              const std::vector<SketchFragment>& fragments, const Scaling& scaling,
                              const FragmentFillOptions& options) {
  const int samples = mdb.samples();
  const int nd = static_cast<int>(scaling.columns.size());
  const Eigen::MatrixXf sketch_f = sketch_match.cast<float>();
  Eigen::MatrixXf queries(static_cast<Eigen::Index>(fragments.size()), samples * nd);
  std::vector<float> row(samples * nd);
  for (size_t f = 0; f < fragments.size(); ++f) {
    double wa, wb;
    MatchingWindow(fragments[f].first, fragments[f].last, options.context_fraction, wa, wb);
    SampleWindow(sketch_f, wa, wb, samples, scaling.columns, row.data());
    for (int s = 0; s < samples; ++s)
      for (int i = 0; i < nd; ++i) queries(f, s * nd + i) = row[s * nd + i] * scaling.factor[i];
  }
  return queries;
}

}  // namespace

Eigen::MatrixXf ScaledSketchFeatures(const MatchingDatabase& mdb, const Eigen::MatrixXd& sketch_match,
                                     const std::vector<SketchFragment>& fragments,
                                     const std::vector<DrivenChannel>& driven, const FragmentFillOptions& options) {
  return ScaledQueries(mdb, sketch_match, fragments, ScalingOf(mdb, driven), options);
}

Eigen::MatrixXf ScaledDatabaseFeatures(const MatchingDatabase& mdb, const std::vector<DrivenChannel>& driven,
                                       const std::vector<int>& fragments, const SketchFragment& query,
                                       const FragmentFillOptions& options) {
  const Scaling scaling = ScalingOf(mdb, driven);
  Eigen::MatrixXf features = ScaledDatabase(mdb, scaling, &fragments);
  const std::vector<int> velocity = VelocityColumns(mdb, scaling, options);
  for (size_t r = 0; r < fragments.size(); ++r) {
    const float ratio = static_cast<float>(StretchSpeedRatio(mdb.fragments()[fragments[r]], query));
    for (int c : velocity) features(static_cast<Eigen::Index>(r), c) *= ratio;
  }
  return features;
}

double StretchSpeedRatio(const DbFragment& db, const SketchFragment& query) {
  return double(std::max(1, db.last - db.first)) / std::max(1, query.last - query.first);
}

namespace {

bool Admissible(const SketchFragment& query, const DbFragment& db, const FragmentFillOptions& options) {
  if (query.rising != db.rising) return false;
  const double ratio = StretchSpeedRatio(db, query);
  return ratio >= options.min_length_ratio && ratio <= options.max_length_ratio;
}

// The velocity columns of a scaled database and their squared norms: with them, a distance
// from the plain dot product of a query and a row becomes the distance to the row's fragment
// stretched by ratio r, whose velocities are r times the row's:
// |q - d|^2 + (r^2 - 1) |d_v|^2 - 2 (r - 1) q_v . d_v.
struct StretchedVelocities {
  StretchedVelocities(const Eigen::MatrixXf& database, std::vector<int> velocity_columns)
      : columns(std::move(velocity_columns)), rows(database.rows(), static_cast<Eigen::Index>(columns.size())) {
    for (size_t k = 0; k < columns.size(); ++k) rows.col(static_cast<Eigen::Index>(k)) = database.col(columns[k]);
    norms = rows.rowwise().squaredNorm();
  }
  // q_v . d_v for every row.
  Eigen::VectorXf Dots(const Eigen::MatrixXf& queries, Eigen::Index query) const {
    Eigen::VectorXf q(static_cast<Eigen::Index>(columns.size()));
    for (size_t k = 0; k < columns.size(); ++k) q[static_cast<Eigen::Index>(k)] = queries(query, columns[k]);
    return rows * q;
  }
  float Correction(Eigen::Index row, float ratio, float dot) const {
    return (ratio * ratio - 1.0f) * norms[row] - 2.0f * (ratio - 1.0f) * dot;
  }
  std::vector<int> columns;
  Eigen::MatrixXf rows;
  Eigen::VectorXf norms;
};

std::vector<Candidate> Best(std::vector<Candidate> all, int k) {
  const auto less = [](const Candidate& a, const Candidate& b) {
    return a.distance < b.distance || (a.distance == b.distance && a.fragment < b.fragment);
  };
  const size_t keep = std::min<size_t>(k, all.size());
  std::partial_sort(all.begin(), all.begin() + keep, all.end(), less);
  all.resize(keep);
  return all;
}

// Runs work(i) for i in [0, n) on `threads` threads (0: one per core).
template <typename Work>
void ForEachIndex(int n, int threads, const Work& work) {
  const int workers = std::max(1, std::min(n, threads > 0 ? threads : int(std::thread::hardware_concurrency())));
  std::vector<std::thread> pool;
  for (int w = 0; w < workers; ++w)
    pool.emplace_back([&, w] {
      for (int i = w; i < n; i += workers) work(i);
    });
  for (std::thread& t : pool) t.join();
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

namespace {

// The K best candidates of each fragment among the database rows, from features scaled as
// Scale does (one query row per fragment).
std::vector<std::vector<Candidate>> BestMatches(const MatchingDatabase& mdb, const Eigen::MatrixXf& queries,
                                                const Eigen::MatrixXf& database,
                                                const std::vector<SketchFragment>& fragments,
                                                const std::vector<int>& velocity_columns,
                                                const FragmentFillOptions& options) {
  const Eigen::VectorXf db_norms = database.rowwise().squaredNorm();
  const Eigen::VectorXf query_norms = queries.rowwise().squaredNorm();
  const StretchedVelocities velocity(database, velocity_columns);
  const int nf = static_cast<int>(fragments.size());
  std::vector<std::vector<Candidate>> result(nf);
  auto work = [&](int f) {
    const Eigen::VectorXf dots = database * queries.row(f).transpose();
    const Eigen::VectorXf velocity_dots = velocity.Dots(queries, f);
    std::vector<Candidate> admissible, any;
    admissible.reserve(mdb.fragments().size());
    for (Eigen::Index r = 0; r < dots.size(); ++r) {
      const float ratio = static_cast<float>(StretchSpeedRatio(mdb.fragments()[r], fragments[f]));
      const float d = std::max(
          0.0f, query_norms[f] + db_norms[r] - 2.0f * dots[r] + velocity.Correction(r, ratio, velocity_dots[r]));
      const Candidate c{static_cast<int>(r), d};
      if (Admissible(fragments[f], mdb.fragments()[r], options)) {
        admissible.push_back(c);
      } else if (admissible.empty()) {
        any.push_back(c);
      }
    }
    result[f] = Best(admissible.empty() ? std::move(any) : std::move(admissible), options.candidates);
  };
  ForEachIndex(nf, options.threads, work);
  return result;
}

}  // namespace

std::vector<std::vector<Candidate>> MatchFragments(const MatchingDatabase& mdb, const Eigen::MatrixXd& sketch_match,
                                                   const std::vector<SketchFragment>& fragments,
                                                   const std::vector<DrivenChannel>& driven,
                                                   const FragmentFillOptions& options) {
  const Scaling scaling = ScalingOf(mdb, driven);
  return BestMatches(mdb, ScaledQueries(mdb, sketch_match, fragments, scaling, options), ScaledDatabase(mdb, scaling),
                     fragments, VelocityColumns(mdb, scaling, options), options);
}

std::vector<std::vector<Candidate>> MatchFragmentsBySet(const MatchingDatabase& mdb,
                                                        const Eigen::MatrixXd& sketch_match,
                                                        const std::vector<SketchFragment>& fragments,
                                                        const std::vector<std::vector<DrivenChannel>>& sets,
                                                        const std::vector<int>& set_of,
                                                        const FragmentFillOptions& options) {
  std::vector<std::vector<Candidate>> result(fragments.size());
  if (sets.empty()) return result;
  // The database is gathered once; sets over the same channels only rescale its columns.
  const Scaling first = ScalingOf(mdb, sets.front());
  const Eigen::MatrixXf gathered = ScaledDatabase(mdb, first);
  for (size_t set = 0; set < sets.size(); ++set) {
    std::vector<SketchFragment> some;
    std::vector<size_t> index;
    for (size_t i = 0; i < fragments.size(); ++i)
      if (set_of[i] == static_cast<int>(set)) {
        some.push_back(fragments[i]);
        index.push_back(i);
      }
    if (some.empty()) continue;
    const Scaling scaling = ScalingOf(mdb, sets[set]);
    Eigen::MatrixXf other;
    if (set > 0 && scaling.columns == first.columns) {
      const Eigen::VectorXf ratio = scaling.factor.cwiseQuotient(first.factor);
      other = gathered * ratio.replicate(mdb.samples(), 1).asDiagonal();
    } else if (set > 0) {
      other = ScaledDatabase(mdb, scaling);
    }
    const Eigen::MatrixXf& database = set > 0 ? other : gathered;
    std::vector<std::vector<Candidate>> matched =
        BestMatches(mdb, ScaledQueries(mdb, sketch_match, some, scaling, options), database, some,
                    VelocityColumns(mdb, scaling, options), options);
    for (size_t k = 0; k < index.size(); ++k) result[index[k]] = std::move(matched[k]);
  }
  return result;
}

std::vector<float> FragmentEnergies(const MatchingDatabase& mdb, const Eigen::MatrixXd& sketch_match,
                                    const std::vector<SketchFragment>& fragments,
                                    const std::vector<DrivenChannel>& driven, const FragmentFillOptions& options) {
  const Eigen::VectorXf norms =
      ScaledQueries(mdb, sketch_match, fragments, ScalingOf(mdb, driven), options).rowwise().squaredNorm();
  return std::vector<float>(norms.data(), norms.data() + norms.size());
}

std::vector<float> NearestOtherTakeDistances(const MatchingDatabase& mdb,
                                             const std::vector<int>& queries,
                                             const std::vector<DrivenChannel>& driven,
                                             const FragmentFillOptions& options) {
  const Scaling scaling = ScalingOf(mdb, driven);
  const Eigen::MatrixXf database = ScaledDatabase(mdb, scaling);
  const Eigen::VectorXf norms = database.rowwise().squaredNorm();
  const StretchedVelocities velocity(database, VelocityColumns(mdb, scaling, options));
  const std::vector<DbFragment>& all = mdb.fragments();
  std::vector<float> nearest(queries.size(), std::numeric_limits<float>::infinity());
  ForEachIndex(static_cast<int>(queries.size()), options.threads, [&](int q) {
    const int row = queries[q];
    const DbFragment& own = all[row];
    const SketchFragment as_sketch{own.first, own.last, own.rising};
    const Eigen::VectorXf dots = database * database.row(row).transpose();
    const Eigen::VectorXf velocity_dots = velocity.Dots(database, row);
    for (Eigen::Index r = 0; r < dots.size(); ++r) {
      if (all[r].clip == own.clip || !Admissible(as_sketch, all[r], options)) continue;
      const float ratio = static_cast<float>(StretchSpeedRatio(all[r], as_sketch));
      const float d = norms[row] + norms[r] - 2.0f * dots[r] + velocity.Correction(r, ratio, velocity_dots[r]);
      nearest[q] = std::min(nearest[q], std::max(0.0f, d));
    }
  });
  return nearest;
}

}  // namespace mocapfill
