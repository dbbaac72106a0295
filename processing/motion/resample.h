// Resampling a uniformly sampled clip to another frame rate: every
// stage works at one working rate (default 30 Hz), so clips from 120 Hz captures or from
// keyed sketches imported at their own rate are brought onto one frame grid first.
#pragma once

#include "processing/core/motion_clip.h"
#include "processing/core/status.h"

namespace mocapfill {

// How translations are interpolated between source frames. Rotations always use slerp
// (short arc, the clip is hemisphere-continuous).
enum class TranslationInterpolation {
  kLinear,  // piecewise linear: never overshoots, C0
  kCubic,   // uniform Catmull-Rom through the source samples: C1, may overshoot slightly
};

struct ResampleOptions {
  double rate_hz = 30.0;  // output rate (frames per second); must be finite and > 0
  TranslationInterpolation translation = TranslationInterpolation::kCubic;

  // Fails with kInvalidArgument naming the field when rate_hz is not finite and positive.
  Status Validate() const;
};

// Number of output frames covering the clip's duration at `rate_hz`:
// floor(duration_s * rate_hz + 1e-6) + 1, so a clip never gains time at its end.
int ResampledFrameCount(const MotionClip& clip, double rate_hz);

// Samples `clip` at times f / options.rate_hz, f = 0 .. ResampledFrameCount - 1.
// Rotations: slerp between the two neighbouring source frames; translations: as chosen
// (only joints with translation_animated; others keep their constant value). Keys are
// mapped to the nearest output frame (ties to the earlier frame), duplicates removed, so a
// keyed source stays keyed. The output is hemisphere-continuous and has the same name,
// joints and translation_animated flags. When the rate already equals the clip's rate
// (within 1e-9 relative) the clip is returned unchanged.
// Errors: invalid options (kInvalidArgument); a clip with no frames or an invalid rate
// (kInvalidData).
// A clip with explicit frame times (not uniform) is sampled at the same output times by
// its frame times: slerp between the neighbouring frames, translations linear or a cubic
// Hermite with finite-difference tangents; keys go to the output frame nearest their
// frame's time. The output is uniform (even when the nominal rate equals options.rate_hz).
Result<MotionClip> ResampleClip(const MotionClip& clip, const ResampleOptions& options);

}  // namespace mocapfill
