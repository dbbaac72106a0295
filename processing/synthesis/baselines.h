// Baseline fill methods, the yardsticks every method is evaluated against: "mean" keeps the
// sketch and puts every missing joint at the database mean pose; "nn" copies the missing joints, at every key frame, from
// the database frame nearest in the keyed channels and interpolates between key frames.
#pragma once

#include <Eigen/Core>

#include "processing/core/motion_database.h"
#include "processing/synthesis/fragment_fill_options.h"
#include "processing/synthesis/sketch_signals.h"

namespace mocapfill {

// Sets every unkeyed channel of `out` to 0 (tangent coordinates: the database mean rotation;
// root features: standing still).
void FillMean(const SketchSignals& sketch, Eigen::MatrixXd& out);

// For every key frame, finds the database frame nearest in the keyed channels (normalised by
// each channel's database standard deviation) and copies its unkeyed channels; interpolates
// linearly between key frames. Returns the database rows used (one per key frame).
std::vector<int> FillNearest(const MotionDatabase& db, const SketchSignals& sketch, const FragmentFillOptions& options,
                             Eigen::MatrixXd& out);

// Standard deviation of every database channel (>= 1e-6), float.
Eigen::VectorXf ChannelSigma(const MotionDatabase& db);

}  // namespace mocapfill
