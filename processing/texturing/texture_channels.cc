#include "processing/texturing/texture_channels.h"

#include <algorithm>

#include "processing/core/status.h"
#include "processing/filtering/pyramid.h"
#include "processing/texturing/activity_gain.h"

namespace mocapfill {

int TextureBandCount(int key_spacing, double rate_hz) {
  const double nyquist = rate_hz / (2.0 * std::max(1, key_spacing));
  int count = 0;
  while (count < 16 && BandPeakHz(count, rate_hz) > nyquist) ++count;
  return count;
}

namespace {

Eigen::MatrixXd Columns(const Eigen::MatrixXd& m, const std::vector<int>& channels) {
  Eigen::MatrixXd out(m.rows(), channels.size());
  for (size_t i = 0; i < channels.size(); ++i) out.col(i) = m.col(channels[i]);
  return out;
}

Result<Pyramid> TexturePyramid(const Eigen::MatrixXd& signal, int texture_bands, double rate_hz) {
  PyramidOptions options;
  options.levels = texture_bands;
  return BuildPyramid(signal, rate_hz, options);
}

// Scales the detail of the activity channels (columns of `detail`, laid out as `channels`).
void MatchActivity(const Eigen::MatrixXd& smooth_low, const std::vector<int>& channels, const ActivityMatch& activity,
                   int texture_bands, double rate_hz, Eigen::MatrixXd& detail) {
  std::vector<int> columns, scaled;
  for (size_t i = 0; i < channels.size(); ++i)
    if (std::find(activity.channels.begin(), activity.channels.end(), channels[i]) != activity.channels.end()) {
      columns.push_back(static_cast<int>(i));
      scaled.push_back(channels[i]);
    }
  if (columns.empty()) return;
  Result<Pyramid> seen = TexturePyramid(Columns(*activity.source_as_keyed, scaled), texture_bands, rate_hz);
  if (!seen.ok()) return;
  const Eigen::MatrixXd gain = ActivityGain(Columns(smooth_low, columns), seen->residual, rate_hz,
                                            activity.window_s, activity.floor_per_s);
  for (size_t i = 0; i < columns.size(); ++i) detail.col(columns[i]).array() *= gain.col(i).array();
}

}  // namespace

void TextureChannels(const Eigen::MatrixXd& smooth, const Eigen::MatrixXd& source, const std::vector<int>& channels,
                     int texture_bands, double rate_hz, Eigen::MatrixXd& out, int finest_band,
                     const ActivityMatch& activity) {
  finest_band = std::max(0, finest_band);
  if (texture_bands <= finest_band || channels.empty() || smooth.rows() < 2) return;
  const Eigen::MatrixXd b = Columns(source, channels);
  Result<Pyramid> pa = TexturePyramid(Columns(smooth, channels), texture_bands, rate_hz);
  Result<Pyramid> pb = TexturePyramid(b, texture_bands, rate_hz);
  if (!pa.ok() || !pb.ok()) return;
  Eigen::MatrixXd detail = b - pb->residual;  // the source's high bands
  for (int k = 0; k < finest_band; ++k) detail -= pb->bands[k];
  if (activity.source_as_keyed != nullptr)
    MatchActivity(pa->residual, channels, activity, texture_bands, rate_hz, detail);
  const Eigen::MatrixXd textured = pa->residual + detail;
  for (size_t i = 0; i < channels.size(); ++i) out.col(channels[i]) = textured.col(i);
}

void LowBandChannels(const Eigen::MatrixXd& smooth, const std::vector<int>& channels, int texture_bands,
                     double rate_hz, Eigen::MatrixXd& out) {
  if (texture_bands <= 0 || channels.empty() || smooth.rows() < 2) return;
  Result<Pyramid> p = TexturePyramid(Columns(smooth, channels), texture_bands, rate_hz);
  if (!p.ok()) return;
  for (size_t i = 0; i < channels.size(); ++i) out.col(channels[i]) = p->residual.col(i);
}

}  // namespace mocapfill
