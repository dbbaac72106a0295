// What the BVH writer will write for each joint: its channel layout (the source's, or a
// default for non-BVH sources, widened when the motion needs more channels), its OFFSET,
// and its Euler angles per frame, continuous over time.
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "formats/bvh/bvh_common.h"
#include "formats/motion_io.h"
#include "processing/core/scene.h"
#include "processing/core/status.h"

namespace mocapfill::bvh {

struct JointExportPlan {
  ChannelLayout layout;
  // For each channel of the layout that is a rotation: which of the three angles it holds
  // (index into the per-frame angle triple, ordered as layout.order.axes).
  std::vector<int> angle_index;
  Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();  // in the parent's (scaled) frame
  Eigen::Vector3d parent_scale = Eigen::Vector3d::Ones();  // applied to animated translations
  std::vector<std::array<double, 3>> angles_deg;       // per frame, in layout.order
};

// Plans every joint of `skeleton` for `clip` (which must validate against it).
// `bvh_layouts` says whether joints without bvh_channels had none in the source (a BVH
// source) rather than being non-BVH joints that get the default layout. With
// BvhLayout::kStandard, every joint gets three rotations (in its source's rotation order)
// and, only when its translation moves, XYZ positions with a zero OFFSET.
Result<std::vector<JointExportPlan>> PlanBvhExport(const Skeleton& skeleton, const MotionClip& clip,
                                                   bool bvh_layouts, BvhLayout kind = BvhLayout::kSource);

}  // namespace mocapfill::bvh
