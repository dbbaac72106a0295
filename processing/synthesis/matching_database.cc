#include "processing/synthesis/matching_database.h"

#include <algorithm>
#include <cmath>
#include <thread>

#include "processing/analysis/phases.h"
#include "processing/filtering/pyramid.h"

namespace mocapfill {

namespace {

// The smallest channel scale (radians for joint channels, metres and metres per second for
// the root's): a channel the database hardly moves, such as a knee's axes other than its
// hinge, tells motions apart by nothing but noise, and scaled to unit spread it would let a
// sketch's degree or two of twist from another rig outweigh everything else.
constexpr float kMinSigma = 0.02f;

// Which key phases of the sketch filter to build: every phase, or `wanted` evenly spread.
std::vector<int> PhasesToBuild(int spacing, int wanted) {
  std::vector<int> phases;
  const int count = wanted <= 0 ? spacing : std::min(spacing, wanted);
  for (int i = 0; i < count; ++i) phases.push_back(i * spacing / count);
  return phases;
}

// Sketch filter of one clip's keyed columns (block column k holds channel columns[k]) at one phase.
void FilterKeyed(Eigen::MatrixXd& block, const std::vector<int>& columns, int num_joints,
                 const std::vector<int>& keys) {
  for (int k = 0; k < block.cols(); ++k) {
    const int c = columns[k];
    const bool velocity = c >= 3 * num_joints && IsRootVelocityFeature(c - 3 * num_joints);
    if (velocity) {
      IntervalMeanBetweenKeys(block.middleCols(k, 1), keys);
    } else {
      LerpBetweenKeys(block.middleCols(k, 1), keys);
    }
  }
}

struct ClipOutput {
  std::vector<DbFragment> fragments;
  std::vector<float> features;
  Status status;
};

}  // namespace

void SampleWindow(const Eigen::Ref<const Eigen::MatrixXf>& rows, double first, double last, int samples,
                  const std::vector<int>& columns, float* out) {
  const int n = static_cast<int>(rows.rows());
  const int nc = static_cast<int>(columns.size());
  for (int s = 0; s < samples; ++s) {
    const double t = std::clamp(first + (last - first) * s / (samples - 1), 0.0, double(n - 1));
    const int a = std::min(static_cast<int>(t), n - 1), b = std::min(a + 1, n - 1);
    const float u = static_cast<float>(t - a);
    for (int i = 0; i < nc; ++i) out[s * nc + i] = (1.0f - u) * rows(a, columns[i]) + u * rows(b, columns[i]);
  }
}

void MatchingWindow(int first, int last, double context_fraction, double& window_first, double& window_last) {
  const double extra = context_fraction * (last - first);
  window_first = first - extra;
  window_last = last + extra;
}

Eigen::MatrixXd MatchingSignal(const Eigen::MatrixXd& block, double rate_hz, const FragmentFillOptions& options) {
  if (options.match_signal == MatchSignal::kLowPass || block.rows() < 2) return block;
  const int band = BandForFrequency(options.match_band_hz, rate_hz, 16);
  PyramidOptions pyramid;
  pyramid.levels = band + 1;
  Result<Pyramid> p = BuildPyramid(block, rate_hz, pyramid);
  if (!p.ok()) return Eigen::MatrixXd::Zero(block.rows(), block.cols());
  return p->bands[band];
}

Eigen::VectorXd BandOf(const Eigen::VectorXd& channel, double rate_hz, int band) {
  if (channel.size() < 2) return Eigen::VectorXd::Zero(channel.size());
  PyramidOptions pyramid;
  pyramid.levels = band + 1;
  Result<Pyramid> p = BuildPyramid(channel, rate_hz, pyramid);
  if (!p.ok()) return Eigen::VectorXd::Zero(channel.size());
  return p->bands[band].col(0);
}

int MatchingDatabase::Row(int clip, int frame) const { return clip_first_[clip] + frame; }

bool MatchingDatabase::Serves(const SketchSignals& sketch, int master_channel, int fragment_band,
                              const FragmentFillOptions& options) const {
  return keyed_ == sketch.keyed && spacing_ == sketch.key_spacing && master_ == master_channel &&
         band_ == fragment_band && phases_ == options.db_phases && signal_ == options.match_signal &&
         samples_ == options.match_samples && match_band_hz_ == options.match_band_hz &&
         context_ == options.context_fraction;
}

Result<MatchingDatabase> MatchingDatabase::Build(const MotionDatabase& db,
                                                 const SketchSignals& sketch,
                                                 int master_channel,
                                                 int fragment_band,
                                                 const FragmentFillOptions& options) {
  if (db.num_clips() == 0) return InvalidData("the database has no clips");
  MatchingDatabase m;
  m.keyed_ = sketch.keyed;
  m.spacing_ = sketch.key_spacing;
  m.master_ = master_channel;
  m.band_ = fragment_band;
  m.phases_ = options.db_phases;
  m.signal_ = options.match_signal;
  m.samples_ = options.match_samples;
  m.match_band_hz_ = options.match_band_hz;
  m.context_ = options.context_fraction;
  const int channels = db.num_channels(), nj = db.num_joints();
  const double rate = db.rate_hz();
  const std::vector<int> phases = PhasesToBuild(sketch.key_spacing, options.db_phases);
  const int row_size = options.match_samples * channels;

  // Only the keyed columns differ between phases; the others are sampled from the clip as captured.
  std::vector<int> keyed_columns, keyed_index(channels, -1);
  for (int c = 0; c < channels; ++c)
    if (sketch.keyed[c]) {
      keyed_index[c] = static_cast<int>(keyed_columns.size());
      keyed_columns.push_back(c);
    }
  const int master_column = keyed_index[master_channel];
  std::vector<ClipOutput> outputs(db.num_clips());
  auto work_clip = [&](int i) {
    ClipOutput& out = outputs[i];
    const Eigen::MatrixXd raw = db.ClipRows(db.signals(), i).cast<double>();
    const int n = static_cast<int>(raw.rows());
    const Eigen::MatrixXf raw_match = MatchingSignal(raw, rate, options).cast<float>();
    Eigen::MatrixXd keyed_raw(n, keyed_columns.size());
    for (size_t k = 0; k < keyed_columns.size(); ++k) keyed_raw.col(k) = raw.col(keyed_columns[k]);
    for (int phase : phases) {
      Eigen::MatrixXd filtered = keyed_raw;
      FilterKeyed(filtered, keyed_columns, nj, PhaseKeys(n, sketch.key_spacing, phase));
      const Eigen::VectorXd master = master_column >= 0 ? Eigen::VectorXd(filtered.col(master_column))
                                                        : Eigen::VectorXd(raw.col(master_channel));
      Result<std::vector<Phase>> cuts = FindPhases(BandOf(master, rate, fragment_band), rate);
      if (!cuts.ok()) {
        out.status = cuts.status().WithContext("database clip '" + db.clip(i).name + "'");
        return;
      }
      const Eigen::MatrixXf filtered_match = MatchingSignal(filtered, rate, options).cast<float>();
      for (const Phase& cut : *cuts) {
        out.fragments.push_back({i, phase, cut.first, cut.last, cut.rising});
        double wa, wb;
        MatchingWindow(cut.first, cut.last, options.context_fraction, wa, wb);
        out.features.resize(out.features.size() + row_size);
        float* row = out.features.data() + out.features.size() - row_size;
        for (int s = 0; s < options.match_samples; ++s) {
          const double t = std::clamp(wa + (wb - wa) * s / (options.match_samples - 1), 0.0, double(n - 1));
          const int a = std::min(static_cast<int>(t), n - 1), b = std::min(a + 1, n - 1);
          const float u = static_cast<float>(t - a);
          for (int c = 0; c < channels; ++c) {
            const int k = keyed_index[c];
            row[s * channels + c] = k >= 0 ? (1.0f - u) * filtered_match(a, k) + u * filtered_match(b, k)
                                           : (1.0f - u) * raw_match(a, c) + u * raw_match(b, c);
          }
        }
      }
    }
  };
  const int workers = std::max(1, options.threads > 0 ? options.threads : int(std::thread::hardware_concurrency()));
  std::vector<std::thread> threads;
  for (int w = 0; w < workers; ++w)
    threads.emplace_back([&, w] {
      for (int i = w; i < db.num_clips(); i += workers) work_clip(i);
    });
  for (std::thread& t : threads) t.join();

  size_t total = 0;
  for (const ClipOutput& out : outputs) {
    RETURN_IF_ERROR(out.status);
    total += out.fragments.size();
  }
  m.features_.resize(static_cast<Eigen::Index>(total), row_size);
  m.fragments_.reserve(total);
  Eigen::Index row = 0;
  for (const ClipOutput& out : outputs) {
    for (size_t f = 0; f < out.fragments.size(); ++f, ++row) {
      m.fragments_.push_back(out.fragments[f]);
      m.features_.row(row) = Eigen::Map<const Eigen::RowVectorXf>(out.features.data() + f * row_size, row_size);
    }
  }
  m.clip_first_.resize(db.num_clips());
  for (int i = 0; i < db.num_clips(); ++i) m.clip_first_[i] = db.clip(i).first_frame;
  // Channel scales from the unfiltered matching signal of the whole database.
  const Eigen::MatrixXd all_match = MatchingSignal(db.signals().cast<double>(), rate, options);
  const Eigen::RowVectorXd mean = all_match.colwise().mean();
  const Eigen::RowVectorXd var = (all_match.rowwise() - mean).array().square().colwise().mean();
  m.sigma_ = var.cwiseSqrt().transpose().cast<float>().cwiseMax(kMinSigma);
  return m;
}

}  // namespace mocapfill
