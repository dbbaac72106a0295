// Pieces every fill method shares, the fragment methods and baselines here
// (fragment_fill_engine.cc) as the PCA-based ones (processing/hybrid, processing/fill): the
// checks of a sketch, stage timing for reports, which joints a fill must leave alone, turning
// signals back into a clip, and key residuals per joint.
#pragma once

#include <Eigen/Core>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/status.h"
#include "processing/core/motion_database.h"
#include "processing/synthesis/fragment_fill_report.h"
#include "processing/synthesis/sketch_signals.h"

namespace mocapfill {

// A sketch a fill can take: at least one frame (else kInvalidData), uniformly sampled and at
// the database rate (else kInvalidArgument).
Status CheckFillSketch(const MotionDatabase& db, const MotionClip& sketch);

// Wall-clock time per named stage, appended to a report (repeated stages are summed).
class StageTimer {
 public:
  explicit StageTimer(FragmentFillReport& report) : report_(report), start_(std::chrono::steady_clock::now()) {}
  // Records the time since the previous mark under `stage`.
  void Mark(const std::string& stage) {
    const auto now = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(now - start_).count();
    start_ = now;
    for (StageTime& t : report_.stages)
      if (t.stage == stage) {
        t.seconds += s;
        return;
      }
    report_.stages.push_back({stage, s});
  }

 private:
  FragmentFillReport& report_;
  std::chrono::steady_clock::time_point start_;
};

// Per joint: 1 when the fill must not change it (keyed, or an ancestor of the motion root,
// whose transform ComposeClip takes from the sketch).
std::vector<std::uint8_t> FixedJoints(const MotionDatabase& db, const SketchSignals& s);

// Whether the sketch keys the root features (the motion root has translation keys).
bool RootFeaturesKeyed(const MotionDatabase& db, const SketchSignals& s);

// Signals (frames x database channels) -> clip; fixed joints that were not textured keep the
// sketch's exact rotations. A root the sketch keys keeps the sketch's trajectory, or when
// textured its travel as the signals integrate to it, pinned onto the sketch's translation keys,
// with its height a monotone cubic through the sketch's height keys. Every frame of the result
// is keyed.
Result<MotionClip> ComposeFill(const MotionDatabase& db, const SketchSignals& s, const Eigen::MatrixXd& out,
                               const MotionClip& sketch, bool textured);

// Fills report.joints and the key errors (output vs sketch at its rotation keys, degrees).
void ReportJoints(const MotionDatabase& db, const SketchSignals& s, const MotionClip& sketch, const MotionClip& out,
                  bool textured, FragmentFillReport& report);

}  // namespace mocapfill
