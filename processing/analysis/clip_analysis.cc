#include "processing/analysis/clip_analysis.h"

#include <cmath>
#include <string>

#include "processing/analysis/band_energy.h"

namespace mocapfill {

Status ClipAnalysisOptions::Validate() const {
  RETURN_IF_ERROR(pyramid.Validate());
  RETURN_IF_ERROR(phases.Validate());
  if (!std::isfinite(phase_band_hz) || phase_band_hz <= 0.0) return InvalidArgument("analysis: phase_band_hz must be > 0");
  if (master_axis < -1 || master_axis > 2) return InvalidArgument("analysis: master_axis must be -1, 0, 1 or 2");
  return OkStatus();
}

Result<ClipAnalysis> AnalyzeClip(const Skeleton& skeleton, const MotionClip& clip, const ClipAnalysisOptions& options) {
  RETURN_IF_ERROR(options.Validate());
  RETURN_IF_ERROR(clip.Validate(skeleton));
  RETURN_IF_ERROR(RequireUniform(clip, "analyze"));
  if (options.master_joint < -1 || options.master_joint >= skeleton.num_joints())
    return InvalidArgument("analysis: master joint index " + std::to_string(options.master_joint) + " is out of range");
  ClipAnalysis out;
  if (options.reference) {
    out.reference = *options.reference;
  } else {
    const MotionClip* clips[] = {&clip};
    out.reference = ComputeTangentReference(skeleton, clips, FindMotionRoot(skeleton, clips));
  }
  out.signals = DecomposeClip(skeleton, clip, out.reference);
  Eigen::MatrixXd all(clip.num_frames, out.signals.tangent.cols() + out.signals.root_features.cols());
  all << out.signals.tangent, out.signals.root_features;
  ASSIGN_OR_RETURN(out.pyramid, BuildPyramid(all, clip.sample_rate_hz, options.pyramid));
  if (out.pyramid.levels() < 1) return InvalidArgument("analysis: clip '" + clip.name + "' is too short to filter");

  std::vector<std::vector<int>> groups;
  for (int j = 0; j < skeleton.num_joints(); ++j) groups.push_back({3 * j, 3 * j + 1, 3 * j + 2});
  out.band_energy_rad2 = BandEnergies(out.pyramid, groups);
  out.phase_band = BandForFrequency(options.phase_band_hz, clip.sample_rate_hz, out.pyramid.levels());

  // Master channel: the most energetic one in the phase band unless the caller chose.
  const Eigen::MatrixXd& band = out.pyramid.bands[out.phase_band];
  double best = -1.0;
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    if (options.master_joint >= 0 && j != options.master_joint) continue;
    for (int a = 0; a < 3; ++a) {
      if (options.master_axis >= 0 && a != options.master_axis) continue;
      const double energy = band.col(3 * j + a).squaredNorm();
      if (energy > best) best = energy, out.master_joint = j, out.master_axis = a;
    }
  }
  ASSIGN_OR_RETURN(out.phases, FindPhases(band.col(3 * out.master_joint + out.master_axis), clip.sample_rate_hz,
                                          options.phases));
  return out;
}

}  // namespace mocapfill
