// Texturing (Pullen and Bregler 2002): a smooth motion, such as a keyframed sketch interpolated
// between its keys or a PCA fit, takes the high-frequency bands of a detailed one (captured or
// synthesised) on chosen channels: the bands above the keys' Nyquist rate, which the keys
// cannot have set. The fragment methods texture keyed channels, the hybrid every channel, the
// graph's `texture` node the joints it is given.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace mocapfill {

// Number of Laplacian bands above the keys' Nyquist rate (texture bands):
// bands whose peak exceeds rate_hz / (2 * key_spacing). At 30 Hz with keys every 8 frames: 3.
int TextureBandCount(int key_spacing, double rate_hz);

// Detail as lively as the sketch (activity_gain.h): on `channels`, the source's detail is scaled
// per frame by ActivityGain between G_kt(smooth) and G_kt(source_as_keyed), the source sampled
// at the sketch's keys and interpolated between them as the sketch is, so that both are seen
// through the same keys (a take seen whole moves more than lines between its keys do, so it
// would always seem the livelier).
struct ActivityMatch {
  const Eigen::MatrixXd* source_as_keyed = nullptr;  // as `source`; nullptr: no scaling
  std::vector<int> channels;                          // among TextureChannels' channels
  double window_s = 1.0;
  double floor_per_s = 0.01;
};

// Channel a of `out` becomes G_kt(smooth) + sum_{finest_band <= k < kt} L_k(source) for every
// listed a, with kt = texture_bands and pyramids over the whole clip; `smooth` and `source` are
// frames x channels with the same rows. finest_band > 0 leaves the source's finest bands out:
// the finest detail of another take is uncorrelated with the motion being filled, so it adds
// error and jerk rather than likeness. `activity` scales the detail of some channels to the
// sketch's liveliness. Does nothing for texture_bands <= finest_band, no channel or fewer than
// two frames.
void TextureChannels(const Eigen::MatrixXd& smooth, const Eigen::MatrixXd& source, const std::vector<int>& channels,
                     int texture_bands, double rate_hz, Eigen::MatrixXd& out, int finest_band = 0,
                     const ActivityMatch& activity = {});

// Channel a of `out` becomes G_kt(smooth) alone, the texture's low band without any detail
// (for the listed a; nothing for texture_bands <= 0, no channel or fewer than two frames).
void LowBandChannels(const Eigen::MatrixXd& smooth, const std::vector<int>& channels, int texture_bands,
                     double rate_hz, Eigen::MatrixXd& out);

}  // namespace mocapfill
