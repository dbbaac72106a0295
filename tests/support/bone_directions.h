// World bone directions of mapped canonical bones, the rig-independent measure of
// retargeting: a segment from one canonical bone's joint to the next, seen
// in the hips' canonical frame so that two rigs with other local axes compare directly.
#pragma once

#include <utility>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/retargeting/retarget.h"

namespace mocapfill::testing {

using BoneSegment = std::pair<HumanoidBone, HumanoidBone>;

// The torso bones of `rig` (each mapped torso bone to the next mapped one, from spine up),
// then shoulders, arms, legs and feet: every mapped bone's own direction.
std::vector<BoneSegment> BoneSegments(const RigMapping& rig);
// Segments that are one bone on every rig: neck-head, shoulders, arms, legs, feet.
std::vector<BoneSegment> LimbSegments();
// What a viewer sees of the upper body: the trunk (hips to neck), neck-head, shoulders, arms.
std::vector<BoneSegment> UpperBodySegments();

// Per frame and segment (mapped in both rigs): the angle between the two clips' directions
// in the hips' canonical frame (degrees). Frames: the shorter clip's.
std::vector<double> DirectionErrorsDeg(const HumanoidRig& a, const MotionClip& clip_a, const HumanoidRig& b,
                                       const MotionClip& clip_b, const std::vector<BoneSegment>& segments);
double MaxDirectionErrorDeg(const HumanoidRig& a, const MotionClip& clip_a, const HumanoidRig& b,
                            const MotionClip& clip_b, const std::vector<BoneSegment>& segments);
double MeanDirectionErrorDeg(const HumanoidRig& a, const MotionClip& clip_a, const HumanoidRig& b,
                             const MotionClip& clip_b, const std::vector<BoneSegment>& segments);

}  // namespace mocapfill::testing
