// The database as the matcher sees it for one sketch configuration, so that it
// matches like with like: keyed channels pass through the same sketch filter as the sketch (sub-sampled at
// the sketch's key spacing, at every key phase, interpolated between the keys), the result is
// cut into fragments on the master channel's band, and every fragment's driven signals are
// time-stretched to a fixed number of samples so that one matrix product scores a sketch
// fragment against all of them.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/synthesis/fragment_fill_options.h"
#include "processing/synthesis/sketch_signals.h"

namespace mocapfill {

// A fragment of one database clip; frames are clip-local and inclusive.
struct DbFragment {
  int clip = 0;
  int phase = 0;   // key phase of the sketch-filtered copy it was cut from
  int first = 0;
  int last = 0;
  bool rising = false;
};

// Samples the window [first, last] (fractional frames, clamped to the rows) of `rows` at
// `samples` evenly spaced points, linear interpolation, for the listed columns; writes
// samples x columns.size() values sample-major into out.
void SampleWindow(const Eigen::Ref<const Eigen::MatrixXf>& rows, double first, double last, int samples,
                  const std::vector<int>& columns, float* out);

// Matching window of a fragment [first, last]: extended by context_fraction of its length on
// each side.
void MatchingWindow(int first, int last, double context_fraction, double& window_first, double& window_last);

class MatchingDatabase {
 public:
  // Builds the sketch-filtered copy for the sketch's keyed channels and key spacing, cuts it
  // on `master_channel`'s band `fragment_band`, and samples every fragment's matching signal.
  // Errors: a database without clips (kInvalidData).
  static Result<MatchingDatabase> Build(const MotionDatabase& db, const SketchSignals& sketch, int master_channel,
                                        int fragment_band, const FragmentFillOptions& options);

  // Whether this copy serves a sketch (same keyed channels, spacing, master, band, options).
  bool Serves(const SketchSignals& sketch,
              int master_channel,
              int fragment_band,
              const FragmentFillOptions& options) const;

  const std::vector<DbFragment>& fragments() const { return fragments_; }
  // fragments x (samples * channels), sample-major per row: the matching signal of every
  // channel (keyed channels sketch-filtered at the fragment's phase, others as captured).
  const Eigen::MatrixXf& features() const { return features_; }
  int samples() const { return samples_; }
  // Standard deviation of each channel's matching signal over the database (>= 1e-6).
  const Eigen::VectorXf& channel_sigma() const { return sigma_; }
  // Global row of clip-local frame `frame` of clip `clip` in the database matrices.
  int Row(int clip, int frame) const;

 private:
  std::vector<DbFragment> fragments_;
  Eigen::MatrixXf features_;
  Eigen::VectorXf sigma_;
  int samples_ = 0;
  std::vector<int> clip_first_;
  // What the copy was built for.
  std::vector<std::uint8_t> keyed_;
  int spacing_ = 0, master_ = -1, band_ = -1, phases_ = 0;
  MatchSignal signal_ = MatchSignal::kLowPass;
  double match_band_hz_ = 0.0, context_ = 0.0;
};

// The matching signal of a clip-long block of channels: the block itself (kLowPass) or its
// Laplacian band nearest options.match_band_hz (kBand), pyramid on the whole block.
Eigen::MatrixXd MatchingSignal(const Eigen::MatrixXd& block, double rate_hz, const FragmentFillOptions& options);

// Laplacian band `band` of one channel (pyramid with band + 1 levels, clamped ends).
Eigen::VectorXd BandOf(const Eigen::VectorXd& channel, double rate_hz, int band);

}  // namespace mocapfill
