// Assembly of the synthesised channels from the chosen database fragments, seam smoothing,
// texturing of keyed channels and re-pinning of keys (algorithms.md 3a.5-3a.7).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/core/motion_database.h"
#include "processing/synthesis/fragment_matching.h"
#include "processing/synthesis/matching_database.h"
#include "processing/synthesis/sketch_signals.h"

namespace mocapfill {

struct AssemblyInputs {
  const MotionDatabase* db = nullptr;
  const MatchingDatabase* mdb = nullptr;
  const std::vector<SketchFragment>* fragments = nullptr;
  const std::vector<std::vector<Candidate>>* candidates = nullptr;  // ascending distance
  std::vector<int> leads;        // joined candidate per fragment
  int blend = 1;                 // candidates averaged per fragment (the lead always among them)
  std::vector<int> channels;     // channels to write
  double crossfade = 0.0;        // overlap beyond each fragment, share of its length per side
};

// Writes `channels` of every fragment's frames into `out` (frames x channels): the candidates'
// captured signals stretched linearly to the fragment's length, averaged with weights
// exp(-d / mean d) over the lead and the nearest others. Without cross-fade a fragment owns
// [first, last) (the last one its end frame too); with it, each fragment's candidates extend
// `crossfade` of its length beyond both ends (the takes continue there) and overlapping
// fragments are mixed with linear fade weights, so there is no seam to smooth. Returns how
// many candidates each fragment blended.
std::vector<int> AssembleFragments(const AssemblyInputs& in, Eigen::MatrixXd& out);

// Seam smoothing: at every fragment boundary b, each listed channel's jump beyond the expected
// step is split between both sides with a quadratic falloff over `window_frames` (capped at
// half of each adjoining fragment), so values and slopes meet.
void SmoothSeams(Eigen::MatrixXd& out, const std::vector<int>& channels, const std::vector<SketchFragment>& fragments,
                 int window_frames);

// Number of Laplacian bands above the keys' Nyquist rate (texture bands, algorithms.md 3a.1):
// bands whose peak exceeds rate_hz / (2 * key_spacing). At 30 Hz with keys every 8 frames: 3.
int TextureBandCount(int key_spacing, double rate_hz);

// Texturing: keyed channel a becomes G_kt(sketch) + sum_{k < kt} L_k(source), pyramids over
// the whole clip. `source` holds the assembled lead candidates' signals of those channels.
void TextureChannels(const Eigen::MatrixXd& sketch, const Eigen::MatrixXd& source, const std::vector<int>& channels,
                     int texture_bands, double rate_hz, Eigen::MatrixXd& out);

// Re-pinning (motion displacement map): subtracts from each channel the cubic interpolation
// (Catmull-Rom through the keys) of its offsets from the sketch at its key frames, so the keys
// hold exactly and the change fades smoothly in between.
void RepinKeys(const SketchSignals& sketch, const std::vector<int>& channels, Eigen::MatrixXd& out);

}  // namespace mocapfill
