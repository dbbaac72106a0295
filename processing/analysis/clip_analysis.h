// Analysis of one clip in the thesis' terms: its multiresolution pyramid, how much of each
// joint's motion lies in each band (frequency analysis), and its motion phases (cuts where
// the first derivative of a chosen band of a master channel changes sign).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "processing/analysis/phases.h"
#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"
#include "processing/filtering/pyramid.h"
#include "processing/motion/tangent_space.h"

namespace mocapfill {

struct ClipAnalysisOptions {
  PyramidOptions pyramid;         // levels 0 = automatic from the clip length
  double phase_band_hz = 1.0;     // fragmentation band, by frequency (L3 at 30 Hz: the stride)
  int master_joint = -1;          // -1 = the joint with most energy in the phase band
  int master_axis = -1;           // tangent component 0..2; -1 = the one with most energy there
  PhaseOptions phases;
  // Tangent reference (e.g. a database's); nullptr = the clip's own means.
  const TangentReference* reference = nullptr;

  Status Validate() const;
};

struct ClipAnalysis {
  TangentReference reference;
  ClipSignals signals;
  // Pyramid of [tangent | root features] (columns as in ClipSignals, root features last).
  Pyramid pyramid;
  // Per joint (rows) and band (columns 0..levels-1, last column = residual about its mean):
  // mean squared tangent norm, rad^2.
  Eigen::MatrixXd band_energy_rad2;
  int phase_band = 0;
  int master_joint = 0;
  int master_axis = 0;
  std::vector<Phase> phases;
};

// Errors: invalid options, a clip invalid for the skeleton, a master joint/axis out of range,
// a clip too short for one band-pass level (kInvalidArgument).
Result<ClipAnalysis> AnalyzeClip(const Skeleton& skeleton, const MotionClip& clip, const ClipAnalysisOptions& options);

}  // namespace mocapfill
