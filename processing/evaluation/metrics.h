// Scores of a filled clip against the ground truth it was sketched from: MPJPE, angle error,
// NPSS, jitter ratio, foot skating and key fidelity, as the motion-completion literature
// defines them (LaFAN1, Harvey et al. 2020; Zhang et al. 2018). Positions are in
// centimetres relative to the motion root (the hips), so the numbers measure the pose, not
// the trajectory the sketch already fixed.
#pragma once

#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"

namespace mocapfill {

struct FillMetrics {
  // Mean per-joint position error (cm) relative to the hips, over every frame, for joints
  // the sketch did not key (below the hips).
  double mpjpe_unkeyed_cm = 0.0;
  // The same for keyed joints on frames between their keys.
  double mpjpe_keyed_between_cm = 0.0;
  // Mean geodesic angle (deg) between filled and true local rotations of unkeyed joints.
  double angle_unkeyed_deg = 0.0;
  // NPSS (Gopalakrishnan et al. 2019) on the global quaternions of the joints below the hips.
  double npss = 0.0;
  // Mean jerk of filled joint positions over the ground truth's (joints below the hips).
  double jitter_ratio = 0.0;
  // Horizontal foot speed (cm/s) on the truth's contact frames, and the share above 2 cm/s.
  // Summaries pool them over contact frames (a clip with one contact frame must not weigh as
  // much as one with hundreds), so foot_contact_frames is kept.
  double foot_skate_cm_per_s = 0.0;
  double foot_skate_share = 0.0;
  // The part of foot_skate_cm_per_s from the contact frames where the filled foot moves slower
  // than a captured foot may while standing (30 cm/s): a planted foot sliding. The rest is a
  // filled foot still stepping (swinging, landing, lifting) where the capture's stands, a step
  // out of time with the capture's, which keys sparser than a step or synthesised legs leave
  // open. Pooled like foot_skate_cm_per_s.
  double foot_slide_cm_per_s = 0.0;
  long foot_contact_frames = 0;
  // Ground penetration (cm) of the filled foot joints: the floor of a kind of joint (ankles,
  // toes) is the truth's lowest height of either side's joint over the clip (the capture's own
  // floor, whatever its offset); the deepest any of them goes below its floor, and the mean
  // depth over the (frame, joint) pairs that are below it (0 when none is).
  double penetration_max_cm = 0.0;
  double penetration_mean_cm = 0.0;
  // Horizontal speed (cm/s) of the filled foot joints over the steps (frame to next) where they
  // stay within 1 cm of those floors, whatever the capture does meanwhile: feet gliding along
  // the ground, which foot_skate_cm_per_s does not see where the fill steps out of time with the
  // capture. The capture's own (heels and toes roll and pivot on the floor) is the reference.
  // Summaries pool each over its steps.
  double floor_glide_cm_per_s = 0.0;
  long floor_steps = 0;
  double capture_floor_glide_cm_per_s = 0.0;
  long capture_floor_steps = 0;
  // The fastest any filled foot joint moves from one frame to the next, over the fastest the
  // capture's same joint moves, at least 1 m/s (the largest over the foot joints): a foot
  // snapping from one hold to another, or onto a key, outruns anything the capture does (a
  // pop); at most 1 when the fill moves its feet no faster than the capture (the floor keeps a
  // standing capture's shuffles from turning a slow step into a large ratio).
  double foot_peak_ratio = 0.0;
  // Geodesic angle (deg) between output and sketch at keyed (joint, frame) pairs.
  double key_error_mean_deg = 0.0;
  double key_error_max_deg = 0.0;
  // Relative bone-length change, mean over bones and frames (0 for rotation-only output).
  double bone_length_error = 0.0;
  int unkeyed_joints = 0;  // how many joints the unkeyed numbers cover
};

// The metrics that are means over a clip, by their JSON names, for averaging and intervals over
// clips (key_error_max_deg is a maximum and unkeyed_joints a count, so neither is listed).
struct MetricField {
  const char* name;
  double FillMetrics::*field;
};
const std::vector<MetricField>& AveragedMetricFields();

// Scores `filled` against `truth` (same skeleton, same frame count). `sketch` supplies the
// keys (MotionClip::keys) that decide keyed/unkeyed joints and key frames. root_joint is the
// hips (positions are taken relative to it; joints outside its subtree are ignored).
// Errors: mismatched sizes (kInvalidArgument).
Result<FillMetrics> ScoreFill(const Skeleton& skeleton, const MotionClip& truth, const MotionClip& sketch,
                              const MotionClip& filled, int root_joint);

// NPSS of two T x D signals (rows = frames): per dimension, the power spectrum over time
// (squared real part of the DFT, as the reference code does) normalised to sum 1, cumulative
// sums compared by L1 distance, averaged over dimensions weighted by the truth's power.
double Npss(const std::vector<std::vector<double>>& truth, const std::vector<std::vector<double>>& predicted);

}  // namespace mocapfill
