#include "mocapfill/filter.h"

#include "library/api/access.h"
#include "processing/filtering/motion_filter.h"

namespace mocapfill::api {

Scene Filter(const Scene& scene, const FilterOptions& options) {
  mocapfill::Scene out = SceneAccess::Get(scene);
  MultiresFilterOptions filter;
  filter.gains.band_gains = options.gains;
  filter.gains.residual_gain = options.residual_gain;
  filter.pyramid.levels = options.levels;
  for (const std::string& name : options.joints) {
    filter.joints.push_back(ValueOrThrow(FindJointNamed(out.skeleton, name, "joints"), FailureStage::kProcessing));
  }
  ThrowIfError(filter.Validate(), FailureStage::kProcessing);
  for (MotionClip& clip : out.clips) {
    Result<MotionClip> filtered = MultiresFilter(out.skeleton, clip, filter);
    if (!filtered.ok()) ThrowIfError(filtered.status().WithContext("clip '" + clip.name + "'"), FailureStage::kProcessing);
    clip = std::move(filtered).value();
  }
  return SceneAccess::Wrap(std::move(out));
}

}  // namespace mocapfill::api
