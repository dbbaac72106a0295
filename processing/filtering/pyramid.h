// Multiresolution (Gaussian/Laplacian) pyramid over time, after Bruderlin and Williams 1995
// (thesis chapter 3). No subsampling: level k applies the 5-tap
// binomial kernel [1/16, 1/4, 3/8, 1/4, 1/16] with its taps spread 2^k frames apart
// ("a trous"). Every column of the input matrix is one channel (frames are rows), so the
// same code filters tangent coordinates, root features or raw Euler curves.
//
//   G_0 = x,  G_(k+1)[i] = sum_n w[n] * G_k[i + n * 2^k],  L_k = G_k - G_(k+1),
//   x' = residual_gain * G_fb + sum_k g_k * L_k      (exact, x' = x, when all gains are 1).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/core/status.h"

namespace mocapfill {

// What a sample outside [0, m-1] takes.
enum class PyramidBoundary {
  kClamp,     // the nearest end value (Bruderlin-Williams "hold"); the default
  kPeriodic,  // wraps around; only correct for cyclic clips
};

struct PyramidOptions {
  // Number of band-pass levels fb. 0 = automatic: AutomaticLevels(frames, rate_hz, min_band_peak_hz).
  // An explicit value must be in [1, 16]; it may exceed floor(log2 m) (the extra bands are
  // then dominated by the boundary rule), which the caller asked for.
  int levels = 0;
  double min_band_peak_hz = 0.1;  // automatic cap: the lowest band's peak stays >= this (Hz)
  PyramidBoundary boundary = PyramidBoundary::kClamp;

  // Fails with kInvalidArgument naming the field and the allowed range.
  Status Validate() const;
};

// Peak frequency (Hz) of band L_k's magnitude response at sample rate rate_hz, computed from
// the kernel (30 Hz: L0 15, L1 4.2, L2 2.0, L3 0.99, L4 0.49, L5 0.25 Hz). k >= 0.
double BandPeakHz(int band, double rate_hz);

// fb = floor(log2 num_frames), reduced until BandPeakHz(fb - 1) >= min_band_peak_hz; at least
// 1 for num_frames >= 2, 0 for a single frame.
int AutomaticLevels(int num_frames, double rate_hz, double min_band_peak_hz = 0.1);

// Band index (0 .. levels-1) whose peak is nearest to frequency_hz on a log scale.
// Selecting bands by Hz keeps their meaning when the frame rate changes (L3 at 30 Hz
// is L5 at 120 Hz). levels must be >= 1 and frequency_hz > 0.
int BandForFrequency(double frequency_hz, double rate_hz, int levels);

// Bands (ascending indices) whose peak lies within [low_hz, high_hz].
std::vector<int> BandsInRange(double low_hz, double high_hz, double rate_hz, int levels);

// One smoothing step: G_(k+1) from G_k (`level` = k) for every column.
Eigen::MatrixXd SmoothLevel(const Eigen::MatrixXd& g_k, int level, PyramidBoundary boundary);
Eigen::MatrixXf SmoothLevel(const Eigen::MatrixXf& g_k, int level, PyramidBoundary boundary);

// A decomposed signal: bands[k] = L_k (k = 0 .. levels-1) and the residual G_fb, each of the
// input's shape.
struct Pyramid {
  std::vector<Eigen::MatrixXd> bands;
  Eigen::MatrixXd residual;

  int levels() const { return static_cast<int>(bands.size()); }
  // G_k = residual + sum of bands k..fb-1 (G_0 is the input up to rounding); 0 <= k <= levels.
  Eigen::MatrixXd Gaussian(int k) const;
};

// Decomposes every column of `signal` (rows = frames, sampled at rate_hz). Automatic levels
// are resolved from the row count. Errors: invalid options, an empty signal or a non-finite
// sample (kInvalidArgument).
Result<Pyramid> BuildPyramid(const Eigen::MatrixXd& signal, double rate_hz, const PyramidOptions& options);

// Per-band gains of a reconstruction. Gains beyond band_gains.size() are 1. Gains for bands
// beyond the signal's levels are ignored when they are 1 (a gain list written for longer
// clips still applies) and an error otherwise, because they would edit bands the clip does not have.
struct BandGains {
  std::vector<double> band_gains;  // g_0 (highest frequency) ..
  double residual_gain = 1.0;      // gain of G_fb (the slowly varying "average pose")
};

// x' = residual_gain * G_fb + sum_k g_k * L_k. Errors: a gain != 1 for a band beyond the levels,
// non-finite gains (kInvalidArgument).
Result<Eigen::MatrixXd> Reconstruct(const Pyramid& pyramid, const BandGains& gains);

// BuildPyramid then Reconstruct, for callers that only want the filtered signal.
Result<Eigen::MatrixXd> FilterBands(const Eigen::MatrixXd& signal, double rate_hz, const PyramidOptions& options,
                                    const BandGains& gains);

}  // namespace mocapfill
