// Internal to formats: the steps from a parsed BVH (hierarchy, motion header) to a Scene,
// shared by ReadBvh and the streaming BVH-to-.glb converter (formats/fast_convert/bvh_to_glb.h),
// so that both make the same skeleton, units and source record.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "formats/bvh/bvh_hierarchy.h"
#include "formats/bvh/bvh_motion.h"
#include "formats/motion_io.h"
#include "formats/units_axes.h"
#include "processing/core/scene.h"

namespace mocapfill::bvh {

// Rejects an unknown up axis or unit name.
Status CheckImportOptions(const ImportOptions& options);

// The text without a leading UTF-8 byte order mark.
std::string_view WithoutByteOrderMark(std::string_view text);

// The skeleton of the hierarchy, in file units (offsets, End Sites, BVH channel names).
Result<Skeleton> BuildSkeleton(const ParsedHierarchy& hierarchy, const std::string& path);

// Frame-count mismatch: the rows present win; a warning, or an error under strict. No rows
// at all is an error.
Status CheckFrameCount(const MotionHeader& header, int rows, const std::string& path, bool strict,
                       std::vector<std::string>& warnings);

// The unit per `options` (BVH defaults to centimetres; "auto" detects it from the rest pose
// height when centimetres would be implausible), from the skeleton in file units.
Result<UnitChoice> ResolveBvhUnit(const Skeleton& skeleton, const ImportOptions& options);

// The source record of a BVH import: format, path, frame time, declared frames, unit, up axis.
SourceInfo BvhSource(const std::string& path, const MotionHeader& header, const UnitChoice& unit, bool z_up);

// The clip's name: the file's stem.
std::string ClipName(const std::string& path);

bool HasPositionChannels(const Joint& joint);

// A joint whose position channels hold one value over the whole clip is not animated: the
// value `used` (metres) becomes its rest translation, the pose actually used, and the
// original OFFSET is kept for BVH export.
void AdoptConstantPosition(Joint& joint, const Eigen::Vector3d& used);

}  // namespace mocapfill::bvh
