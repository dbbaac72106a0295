// Multiresolution filtering of a whole clip (Bruderlin and Williams 1995; thesis chapter 3):
// the clip goes to signal space (tangent_space.h), each selected channel is decomposed by the
// pyramid, bands are scaled by the gains and the clip is put back together.
//
// Root handling: the motion root's world motion is filtered as heading-invariant root features
// (height, forward/lateral velocity, yaw rate) plus its tilt tangent, then re-integrated.
// Chosen over filtering world translation per axis and root rotation about its mean because
// those wrap (a turning walk leaves the 150-degree range of the mean) and depend on where the
// clip starts; over the Lee-Shin incremental form because features and re-integration are
// exact inverses (unit gains reproduce the clip), never wrap, and are the very channels the
// database and the fill methods use. A gain on a velocity band changes the path travelled in
// that band (a gain > 1 on the step band makes the gait bob and surge more), which is the
// intended meaning of an equaliser on locomotion.
#pragma once

#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/core/status.h"
#include "processing/filtering/pyramid.h"
#include "processing/motion/tangent_space.h"

namespace mocapfill {

struct MultiresFilterOptions {
  BandGains gains;            // g_0 .. (highest band first); missing gains are 1
  PyramidOptions pyramid;     // levels (0 = automatic from the clip length and rate), boundary
  // Joints to filter (indices); empty = every joint. Including the motion root filters the
  // root features and tilt; other joints are filtered in their own tangent coordinates.
  std::vector<int> joints;
  // Reference rotations of the tangent space; nullptr = the clip's own joint means (with
  // root split at FindMotionRoot). Pass a database's reference to filter about its means.
  const TangentReference* reference = nullptr;

  // Checks gains and pyramid options (kInvalidArgument naming the field).
  Status Validate() const;
};

// Filters `clip` (which must be valid for `skeleton`). Unit gains return the clip up to
// floating-point rounding (< 1e-9 rad). The output keeps name, rate, frame count, keys and
// the translations of joints other than the root. Errors: invalid options, a joint index
// out of range, a gain other than 1 for a band the clip does not have (kInvalidArgument).
Result<MotionClip> MultiresFilter(const Skeleton& skeleton, const MotionClip& clip,
                                  const MultiresFilterOptions& options);

}  // namespace mocapfill
