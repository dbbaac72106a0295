// The sketch in signal space: tangent coordinates about the
// database means plus root features, with the keyed channels densified between their keys
// by the same "sketch filter" that is applied to the database before matching, so the two
// are compared like with like (raw capture matched against a smooth sketch does worse than
// the mean pose).
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/motion_database.h"
#include "processing/core/status.h"
#include "processing/motion/tangent_space.h"

namespace mocapfill {

// Channel-wise sketch filter on the rows of `block` (frames x channels of one clip): every
// column keeps its values at `keys` (sorted frame indices) and is linearly interpolated
// between them, held before the first and after the last key.
void LerpBetweenKeys(Eigen::Ref<Eigen::MatrixXd> block, const std::vector<int>& keys);
void LerpBetweenKeys(Eigen::Ref<Eigen::MatrixXf> block, const std::vector<int>& keys);
// The filter for velocity-like columns: each key interval [k_i, k_(i+1)) takes the mean of the
// column over that interval, which is the velocity of a path interpolated linearly between keys.
void IntervalMeanBetweenKeys(Eigen::Ref<Eigen::MatrixXf> block, const std::vector<int>& keys);
void IntervalMeanBetweenKeys(Eigen::Ref<Eigen::MatrixXd> block, const std::vector<int>& keys);

// Keys a database clip of `frames` frames would have in a sketch keyed every `spacing` frames
// starting at `phase`: 0, phase, phase + spacing, ..., last frame.
std::vector<int> PhaseKeys(int frames, int spacing, int phase);

// True for the velocity-like root features (forward, lateral, yaw rate).
bool IsRootVelocityFeature(int feature);

struct SketchSignals {
  int frames = 0;
  int num_joints = 0;
  Eigen::MatrixXd values;                     // frames x channels (database layout)
  std::vector<std::uint8_t> keyed;            // per channel: 1 when the sketch keys it
  std::vector<std::vector<int>> key_frames;   // per channel: its key frames (empty when unkeyed)
  std::vector<int> all_key_frames;            // union over keyed channels, sorted
  int key_spacing = 1;                        // median spacing of the keys, frames
  ClipSignals raw;                            // the sketch decomposed as imported

  int num_channels() const { return static_cast<int>(values.cols()); }
  // The joint a channel belongs to (root features belong to the motion root).
  int JointOf(int channel, int root_joint) const { return channel < 3 * num_joints ? channel / 3 : root_joint; }
};

// Decomposes `sketch` (database skeleton and joint order, database rate) about the database
// reference and densifies its keyed channels. A joint is keyed when it has rotation keys; the
// root features are keyed when the motion root has translation keys. Errors: a clip that
// does not fit the database skeleton, no keyed joint at all (kInvalidData).
Result<SketchSignals> MakeSketchSignals(const MotionDatabase& db, const MotionClip& sketch);

}  // namespace mocapfill
