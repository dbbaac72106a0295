#include "processing/pca/pca_basis.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

namespace mocapfill {

namespace {

// Rows are copied into blocks of this many vectors so that window PCA over a large
// database never materialises the (frames x W*D) window matrix.
constexpr int kChunkRows = 2048;
// Eigenvalues below this fraction of the largest are numerical noise, not directions.
constexpr double kRankTolerance = 1e-10;
// Smoothness sigmas are floored at this fraction of their typical value so that constant
// channels (e.g. a static helper joint) do not get an infinite weight.
constexpr double kAccelFloorFraction = 1e-3;

// Calls fn(block) for consecutive blocks of stacked windows (see StackWindows).
template <typename Fn>
void VisitWindows(const Eigen::MatrixXd& rows, std::span<const int> lengths, int window, int stride, Fn&& fn) {
  const Eigen::Index cols = rows.cols();
  Eigen::MatrixXd block(kChunkRows, window * cols);
  int filled = 0;
  int start = 0;
  for (int length : lengths) {
    for (int s = 0; s + window <= length; s += stride) {
      for (int w = 0; w < window; ++w) block.row(filled).segment(w * cols, cols) = rows.row(start + s + w);
      if (++filled == kChunkRows) {
        fn(block.topRows(filled));
        filled = 0;
      }
    }
    start += length;
  }
  if (filled > 0) fn(block.topRows(filled));
}

// Second differences x[t+1] - 2 x[t] + x[t-1] inside every segment; returns the rows and
// writes the per-segment counts (length - 2, or 0) to `out_lengths`.
Eigen::MatrixXd SecondDifferences(const Eigen::MatrixXd& rows, std::span<const int> lengths,
                                  std::vector<int>& out_lengths) {
  int total = 0;
  for (int length : lengths) total += std::max(0, length - 2);
  Eigen::MatrixXd out(total, rows.cols());
  out_lengths.clear();
  int start = 0, row = 0;
  for (int length : lengths) {
    for (int t = 1; t + 1 < length; ++t, ++row)
      out.row(row) = rows.row(start + t + 1) - 2.0 * rows.row(start + t) + rows.row(start + t - 1);
    out_lengths.push_back(std::max(0, length - 2));
    start += length;
  }
  return out;
}

int ChooseComponentCount(const Eigen::VectorXd& spectrum, const PcaBasisOptions& options) {
  const double total = spectrum.sum();
  int rank = 0;
  while (rank < spectrum.size() && spectrum[rank] > kRankTolerance * spectrum[0]) ++rank;
  double cumulative = 0.0;
  int k = 0;
  while (k < rank) {
    cumulative += spectrum[k++];
    if (cumulative >= options.variance_kept * total * (1.0 - 1e-12)) break;
  }
  return std::max(1, std::min({k, rank, options.max_components}));
}

// Flips each component so its largest-magnitude entry is positive: PCA signs are arbitrary,
// and a fixed convention makes models (and files) reproducible.
void FixSigns(Eigen::MatrixXd& components) {
  for (Eigen::Index k = 0; k < components.cols(); ++k) {
    Eigen::Index arg = 0;
    components.col(k).cwiseAbs().maxCoeff(&arg);
    if (components(arg, k) < 0.0) components.col(k) *= -1.0;
  }
}

Eigen::VectorXd FlooredRms(const Eigen::VectorXd& sum_squares, double count, const Eigen::VectorXd& scale) {
  Eigen::VectorXd rms = count > 0 ? Eigen::VectorXd((sum_squares / count).cwiseSqrt()) : scale;
  for (Eigen::Index i = 0; i < rms.size(); ++i) {
    const double floor = std::max(kAccelFloorFraction * scale[i], 1e-12);
    rms[i] = std::max(rms[i], floor);
  }
  return rms;
}

}  // namespace

Status PcaBasisOptions::Validate() const {
  if (!(variance_kept > 0.0 && variance_kept <= 1.0))
    return InvalidArgument("variance_kept must be in (0, 1], got " + std::to_string(variance_kept));
  if (max_components < 1) return InvalidArgument("max_components must be >= 1, got " + std::to_string(max_components));
  if (window_frames < 1) return InvalidArgument("window_frames must be >= 1, got " + std::to_string(window_frames));
  if (window_stride_frames < 1)
    return InvalidArgument("window_stride_frames must be >= 1, got " + std::to_string(window_stride_frames));
  return OkStatus();
}

Eigen::MatrixXd StackWindows(const Eigen::MatrixXd& rows, std::span<const int> segment_lengths, int window,
                             int stride) {
  int count = 0;
  for (int length : segment_lengths)
    if (length >= window) count += (length - window) / stride + 1;
  Eigen::MatrixXd out(count, window * rows.cols());
  int row = 0;
  VisitWindows(rows, segment_lengths, window, stride, [&](const auto& block) {
    out.middleRows(row, block.rows()) = block;
    row += static_cast<int>(block.rows());
  });
  return out;
}

Status EstimatePcaBasis(const Eigen::MatrixXd& poses, std::span<const int> segment_lengths,
                        const PcaBasisOptions& options, PcaModel& model) {
  RETURN_IF_ERROR(options.Validate());
  const long total_rows = std::accumulate(segment_lengths.begin(), segment_lengths.end(), 0L);
  if (total_rows != poses.rows() || std::any_of(segment_lengths.begin(), segment_lengths.end(),
                                                [](int n) { return n < 0; }))
    return InvalidArgument("segment lengths sum to " + std::to_string(total_rows) + " but there are " +
                           std::to_string(poses.rows()) + " pose rows");
  if (!poses.allFinite()) return InvalidData("pose vectors contain non-finite values");
  const int window = options.window_frames;
  const int stride = window == 1 ? 1 : options.window_stride_frames;
  const Eigen::Index dim = window * poses.cols();

  // Mean, then covariance about it (two passes: numerically safer than one).
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(dim);
  long count = 0;
  VisitWindows(poses, segment_lengths, window, stride, [&](const auto& block) {
    sum += block.colwise().sum().transpose();
    count += block.rows();
  });
  if (count < 2)
    return InvalidData("PCA needs at least 2 vectors, the database gives " + std::to_string(count) +
                       (window > 1 ? " windows of " + std::to_string(window) + " frames" : std::string(" frames")));
  const Eigen::VectorXd mean = sum / static_cast<double>(count);
  Eigen::MatrixXd covariance = Eigen::MatrixXd::Zero(dim, dim);
  VisitWindows(poses, segment_lengths, window, stride, [&](const auto& block) {
    const Eigen::MatrixXd centred = block.rowwise() - mean.transpose();
    covariance.selfadjointView<Eigen::Lower>().rankUpdate(centred.transpose());
  });
  covariance = covariance.selfadjointView<Eigen::Lower>();
  covariance /= static_cast<double>(count - 1);

  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(covariance);
  if (solver.info() != Eigen::Success) return NumericalFailure("covariance eigen-decomposition did not converge");
  const Eigen::VectorXd spectrum = solver.eigenvalues().reverse().cwiseMax(0.0);
  if (!(spectrum[0] > 0.0)) return InvalidData("the database has no variance: every vector is the same");
  const int k = ChooseComponentCount(spectrum, options);
  Eigen::MatrixXd components = solver.eigenvectors().rowwise().reverse().leftCols(k);
  FixSigns(components);

  model.window_frames = window;
  model.num_samples = static_cast<int>(count);
  model.mean = mean;
  model.components = components;
  model.variances = spectrum.head(k);
  model.spectrum = spectrum;
  model.residual_variance = (covariance.diagonal() - components.cwiseAbs2() * model.variances).cwiseMax(0.0);

  // Smoothness statistics (6.2): consecutive windows differ by one frame, so the second
  // difference of the coefficients is the projection of stacked pose second differences.
  std::vector<int> accel_lengths;
  const Eigen::MatrixXd accel = SecondDifferences(poses, segment_lengths, accel_lengths);
  const Eigen::VectorXd channel_scale = poses.rows() > 1 ? Eigen::VectorXd(
      ((poses.rowwise() - poses.colwise().mean()).colwise().squaredNorm() / (poses.rows() - 1.0))
          .cwiseSqrt().transpose()) : Eigen::VectorXd::Ones(poses.cols());
  const double mean_scale = std::max(channel_scale.mean(), 1e-12);
  model.channel_accel_rms = FlooredRms(accel.colwise().squaredNorm().transpose(), static_cast<double>(accel.rows()),
                                       Eigen::VectorXd::Constant(poses.cols(), mean_scale));
  Eigen::VectorXd coefficient_sq = Eigen::VectorXd::Zero(k);
  long accel_count = 0;
  VisitWindows(accel, accel_lengths, window, 1, [&](const auto& block) {
    coefficient_sq += (block * components).colwise().squaredNorm().transpose();
    accel_count += block.rows();
  });
  model.coefficient_accel_rms =
      FlooredRms(coefficient_sq, static_cast<double>(accel_count), model.variances.cwiseSqrt());
  return OkStatus();
}

}  // namespace mocapfill
