#include "processing/texturing/texture_channels.h"

#include <algorithm>

#include "processing/core/status.h"
#include "processing/filtering/pyramid.h"

namespace mocapfill {

int TextureBandCount(int key_spacing, double rate_hz) {
  const double nyquist = rate_hz / (2.0 * std::max(1, key_spacing));
  int count = 0;
  while (count < 16 && BandPeakHz(count, rate_hz) > nyquist) ++count;
  return count;
}

void TextureChannels(const Eigen::MatrixXd& smooth, const Eigen::MatrixXd& source, const std::vector<int>& channels,
                     int texture_bands, double rate_hz, Eigen::MatrixXd& out, int finest_band) {
  finest_band = std::max(0, finest_band);
  if (texture_bands <= finest_band || channels.empty() || smooth.rows() < 2) return;
  Eigen::MatrixXd a(smooth.rows(), channels.size()), b(source.rows(), channels.size());
  for (size_t i = 0; i < channels.size(); ++i) {
    a.col(i) = smooth.col(channels[i]);
    b.col(i) = source.col(channels[i]);
  }
  PyramidOptions options;
  options.levels = texture_bands;
  Result<Pyramid> pa = BuildPyramid(a, rate_hz, options);
  Result<Pyramid> pb = BuildPyramid(b, rate_hz, options);
  if (!pa.ok() || !pb.ok()) return;
  Eigen::MatrixXd textured = pa->residual + (b - pb->residual);  // G_kt(smooth) + high bands(source)
  for (int k = 0; k < finest_band; ++k) textured -= pb->bands[k];
  for (size_t i = 0; i < channels.size(); ++i) out.col(channels[i]) = textured.col(i);
}

}  // namespace mocapfill
