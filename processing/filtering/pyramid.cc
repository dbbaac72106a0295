#include "processing/filtering/pyramid.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace mocapfill {

namespace {

constexpr double kTaps[5] = {1.0 / 16.0, 1.0 / 4.0, 3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0};
constexpr int kMaxLevels = 16;
constexpr double kTwoPi = 6.283185307179586476925;

// Magnitude response of the base kernel at angular frequency omega (rad/sample).
double KernelResponse(double omega) { return 3.0 / 8.0 + 0.5 * std::cos(omega) + 0.125 * std::cos(2.0 * omega); }

// Response of band L_k at frequency f: the low-passes of levels 0..k-1 times the high-pass
// left by level k (a trous: level i's taps are 2^i apart, so it acts at 2^i * omega).
double BandResponse(int band, double frequency_hz, double rate_hz) {
  const double omega = kTwoPi * frequency_hz / rate_hz;
  double response = 1.0;
  for (int i = 0; i < band; ++i) response *= KernelResponse(std::ldexp(omega, i));
  return response * (1.0 - KernelResponse(std::ldexp(omega, band)));
}

int WrapIndex(int i, int m, PyramidBoundary boundary) {
  if (boundary == PyramidBoundary::kClamp) return std::clamp(i, 0, m - 1);
  const int r = i % m;
  return r < 0 ? r + m : r;
}

template <typename Matrix>
Matrix SmoothLevelImpl(const Matrix& g, int level, PyramidBoundary boundary) {
  using Scalar = typename Matrix::Scalar;
  const int m = static_cast<int>(g.rows());
  const int spacing = 1 << level;
  Matrix out(g.rows(), g.cols());
  const Scalar w0 = Scalar(kTaps[0]), w1 = Scalar(kTaps[1]), w2 = Scalar(kTaps[2]);
  // Interior rows need no boundary rule: all taps fall inside [0, m-1].
  const int lo = std::min(2 * spacing, m), hi = std::max(m - 2 * spacing, lo);
  for (Eigen::Index c = 0; c < g.cols(); ++c) {
    const Scalar* x = g.col(c).data();
    Scalar* y = out.col(c).data();
    for (int i = lo; i < hi; ++i)
      y[i] = w0 * (x[i - 2 * spacing] + x[i + 2 * spacing]) + w1 * (x[i - spacing] + x[i + spacing]) + w2 * x[i];
    auto edge = [&](int i) {
      Scalar sum = 0;
      for (int n = -2; n <= 2; ++n) sum += Scalar(kTaps[n + 2]) * x[WrapIndex(i + n * spacing, m, boundary)];
      y[i] = sum;
    };
    for (int i = 0; i < lo; ++i) edge(i);
    for (int i = hi; i < m; ++i) edge(i);
  }
  return out;
}

}  // namespace

Status PyramidOptions::Validate() const {
  if (levels < 0 || levels > kMaxLevels)
    return InvalidArgument("pyramid: levels must be 0 (automatic) or 1.." + std::to_string(kMaxLevels) + ", got " +
                           std::to_string(levels));
  if (!std::isfinite(min_band_peak_hz) || min_band_peak_hz <= 0.0)
    return InvalidArgument("pyramid: min_band_peak_hz must be finite and > 0");
  return OkStatus();
}

namespace {

// Peak of band k at a rate of 1 Hz: a log-spaced grid over (0, Nyquist], then golden-section
// refinement around the best cell. The response depends on f / rate only, so peaks scale
// linearly with the rate.
double NormalisedBandPeak(int band) {
  constexpr double rate_hz = 1.0;
  const double nyquist = 0.5 * rate_hz;
  const double lowest = nyquist * std::ldexp(1.0, -(band + 10));
  constexpr int kGrid = 2048;
  const double log_lo = std::log(lowest), log_hi = std::log(nyquist);
  auto at = [&](double log_f) { return BandResponse(band, std::exp(log_f), rate_hz); };
  int best = kGrid;
  double best_value = -1.0;
  for (int i = 0; i <= kGrid; ++i) {
    const double value = at(log_lo + (log_hi - log_lo) * i / kGrid);
    if (value > best_value) best_value = value, best = i;
  }
  double a = log_lo + (log_hi - log_lo) * std::max(best - 1, 0) / kGrid;
  double b = log_lo + (log_hi - log_lo) * std::min(best + 1, kGrid) / kGrid;
  constexpr double kGolden = 0.6180339887498949;
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double c = b - kGolden * (b - a), d = a + kGolden * (b - a);
    if (at(c) > at(d)) b = d; else a = c;
  }
  return std::min(std::exp(0.5 * (a + b)), nyquist);
}

}  // namespace

double BandPeakHz(int band, double rate_hz) {
  static const std::vector<double> peaks = [] {
    std::vector<double> p;
    for (int k = 0; k <= 2 * kMaxLevels; ++k) p.push_back(NormalisedBandPeak(k));
    return p;
  }();
  if (band >= 0 && band < static_cast<int>(peaks.size())) return peaks[band] * rate_hz;
  return NormalisedBandPeak(band) * rate_hz;
}

int AutomaticLevels(int num_frames, double rate_hz, double min_band_peak_hz) {
  if (num_frames < 2) return 0;
  int levels = std::min(static_cast<int>(std::floor(std::log2(static_cast<double>(num_frames)))), kMaxLevels);
  while (levels > 1 && BandPeakHz(levels - 1, rate_hz) < min_band_peak_hz) --levels;
  return levels;
}

int BandForFrequency(double frequency_hz, double rate_hz, int levels) {
  int best = 0;
  double best_distance = INFINITY;
  for (int k = 0; k < levels; ++k) {
    const double distance = std::abs(std::log(BandPeakHz(k, rate_hz) / frequency_hz));
    if (distance < best_distance) best_distance = distance, best = k;
  }
  return best;
}

std::vector<int> BandsInRange(double low_hz, double high_hz, double rate_hz, int levels) {
  std::vector<int> bands;
  for (int k = 0; k < levels; ++k) {
    const double peak = BandPeakHz(k, rate_hz);
    if (peak >= low_hz && peak <= high_hz) bands.push_back(k);
  }
  return bands;
}

Eigen::MatrixXd SmoothLevel(const Eigen::MatrixXd& g_k, int level, PyramidBoundary boundary) {
  return SmoothLevelImpl(g_k, level, boundary);
}

Eigen::MatrixXf SmoothLevel(const Eigen::MatrixXf& g_k, int level, PyramidBoundary boundary) {
  return SmoothLevelImpl(g_k, level, boundary);
}

Eigen::MatrixXd Pyramid::Gaussian(int k) const {
  Eigen::MatrixXd g = residual;
  for (int i = levels() - 1; i >= k; --i) g += bands[i];
  return g;
}

Result<Pyramid> BuildPyramid(const Eigen::MatrixXd& signal, double rate_hz, const PyramidOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  if (signal.rows() == 0 || signal.cols() == 0) return InvalidArgument("pyramid: the signal is empty");
  if (!std::isfinite(rate_hz) || rate_hz <= 0.0) return InvalidArgument("pyramid: rate_hz must be finite and > 0");
  if (!signal.allFinite()) return InvalidArgument("pyramid: the signal contains a non-finite sample");
  const int levels = options.levels > 0 ? options.levels
                                        : AutomaticLevels(static_cast<int>(signal.rows()), rate_hz, options.min_band_peak_hz);
  Pyramid pyramid;
  pyramid.bands.reserve(levels);
  Eigen::MatrixXd g = signal;
  for (int k = 0; k < levels; ++k) {
    Eigen::MatrixXd next = SmoothLevel(g, k, options.boundary);
    pyramid.bands.push_back(g - next);
    g = std::move(next);
  }
  pyramid.residual = std::move(g);
  return pyramid;
}

Result<Eigen::MatrixXd> Reconstruct(const Pyramid& pyramid, const BandGains& gains) {
  for (size_t k = pyramid.levels(); k < gains.band_gains.size(); ++k)
    if (gains.band_gains[k] != 1.0)
      return InvalidArgument("pyramid: gain " + std::to_string(gains.band_gains[k]) + " for band L" + std::to_string(k) +
                             ", but the signal (" + std::to_string(pyramid.residual.rows()) + " frames) has only " +
                             std::to_string(pyramid.levels()) + " band-pass levels");
  for (double g : gains.band_gains)
    if (!std::isfinite(g)) return InvalidArgument("pyramid: band gains must be finite");
  if (!std::isfinite(gains.residual_gain)) return InvalidArgument("pyramid: residual gain must be finite");
  // Sum from the lowest band up, as the Gaussian levels telescope.
  Eigen::MatrixXd out = gains.residual_gain * pyramid.residual;
  for (int k = pyramid.levels() - 1; k >= 0; --k) {
    const double g = k < static_cast<int>(gains.band_gains.size()) ? gains.band_gains[k] : 1.0;
    if (g == 1.0) out += pyramid.bands[k]; else out += g * pyramid.bands[k];
  }
  return out;
}

Result<Eigen::MatrixXd> FilterBands(const Eigen::MatrixXd& signal, double rate_hz, const PyramidOptions& options,
                                    const BandGains& gains) {
  ASSIGN_OR_RETURN(Pyramid pyramid, BuildPyramid(signal, rate_hz, options));
  return Reconstruct(pyramid, gains);
}

}  // namespace mocapfill
