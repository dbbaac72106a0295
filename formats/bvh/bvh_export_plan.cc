#include "formats/bvh/bvh_export_plan.h"

#include <cmath>

#include "processing/core/rotation.h"

namespace mocapfill::bvh {

namespace {

// A translation component that moves less than this over the clip is written as part of
// the OFFSET; otherwise the joint needs a position channel for it.
constexpr double kStaticComponentToleranceM = 1e-12;
// An Euler angle about an axis the layout does not list must stay this close to zero.
constexpr double kUnlistedAngleToleranceDeg = 1e-8;
// How much closer (sum of the three angle changes) the non-principal Euler solution must
// be before the writer leaves the principal branch.
constexpr double kBranchSwitchMarginDeg = 90.0;

Result<std::vector<Channel>> SourceChannels(const Joint& joint) {
  std::vector<Channel> channels;
  for (const std::string& name : joint.bvh_channels) {
    const std::optional<Channel> channel = ParseChannel(name);
    if (!channel) return InvalidData("joint '" + joint.name + "' has an unknown BVH channel '" + name + "'");
    channels.push_back(*channel);
  }
  return channels;
}

// Non-BVH sources: positions (XYZ) where needed, then rotations in ZXY, the Biovision default.
std::vector<Channel> DefaultChannels(bool with_positions) {
  std::vector<Channel> channels;
  if (with_positions) channels = {Channel::kXposition, Channel::kYposition, Channel::kZposition};
  for (Channel c : {Channel::kZrotation, Channel::kXrotation, Channel::kYrotation}) channels.push_back(c);
  return channels;
}

bool ComponentVaries(const MotionClip& clip, int joint, int axis) {
  const double first = clip.translation(0, joint)[axis];
  for (int f = 1; f < clip.num_frames; ++f)
    if (std::abs(clip.translation(f, joint)[axis] - first) > kStaticComponentToleranceM) return true;
  return false;
}

double Distance(const std::array<double, 3>& a, const std::array<double, 3>& b) {
  return std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
}

// Euler angles nearest the previous frame's (no 360-degree jumps), but on the principal
// branch (middle angle within +-90, what BVH exporters write) unless leaving it saves more
// than kBranchSwitchMarginDeg: a gimbal-lock crossing does (the principal branch would
// turn two channels by 180 degrees), a jump between unrelated poses does not, so a file's
// own numbers come back after a round trip.
std::array<double, 3> ContinuousEuler(const Eigen::Quaterniond& q, const EulerOrder& order,
                                      const std::array<double, 3>& previous) {
  const std::array<double, 3> nearest = QuaternionToEulerDegrees(q, order, &previous);
  if (std::cos(nearest[1] * kRadPerDeg) >= 0.0) return nearest;
  std::array<double, 3> principal = QuaternionToEulerDegrees(q, order);
  for (int i = 0; i < 3; ++i) principal[i] += 360.0 * std::round((previous[i] - principal[i]) / 360.0);
  return Distance(principal, previous) <= Distance(nearest, previous) + kBranchSwitchMarginDeg ? principal : nearest;
}

std::vector<std::array<double, 3>> EulerTrack(const MotionClip& clip, int joint, const EulerOrder& order) {
  std::vector<std::array<double, 3>> angles(clip.num_frames);
  for (int f = 0; f < clip.num_frames; ++f)
    angles[f] = f == 0 ? QuaternionToEulerDegrees(clip.rotation(f, joint), order)
                       : ContinuousEuler(clip.rotation(f, joint), order, angles[f - 1]);
  return angles;
}

bool UnlistedAnglesVanish(const std::vector<std::array<double, 3>>& angles, int num_listed) {
  for (const auto& frame : angles)
    for (int i = num_listed; i < 3; ++i)
      if (std::abs(frame[i]) > kUnlistedAngleToleranceDeg) return false;
  return true;
}

Result<ChannelLayout> Layout(const std::vector<Channel>& channels, const std::string& joint_name) {
  int duplicate = -1;
  ChannelLayout layout = MakeChannelLayout(channels, duplicate);
  if (duplicate >= 0)
    return InvalidData("joint '" + joint_name + "' lists BVH channel '" + ChannelName(channels[duplicate]) + "' twice");
  return layout;
}

// Adds position channels (in front) for the unlisted components when any of them moves.
std::vector<Channel> WithNeededPositions(const MotionClip& clip, int joint, const ChannelLayout& layout) {
  bool moves = false;
  for (int axis = 0; axis < 3 && !moves; ++axis)
    moves = layout.position_slot[axis] < 0 && ComponentVaries(clip, joint, axis);
  if (!moves) return layout.channels;
  std::vector<Channel> channels;
  for (int axis = 0; axis < 3; ++axis)
    if (layout.position_slot[axis] < 0) channels.push_back(static_cast<Channel>(axis));
  channels.insert(channels.end(), layout.channels.begin(), layout.channels.end());
  return channels;
}

bool TranslationVaries(const MotionClip& clip, int joint) {
  for (int axis = 0; axis < 3; ++axis)
    if (ComponentVaries(clip, joint, axis)) return true;
  return false;
}

// The standard layout: XYZ positions when the translation moves, then the three rotations
// in the order of the source's rotation channels (unlisted axes after them).
Result<std::vector<Channel>> StandardChannels(const Skeleton& skeleton, const MotionClip& clip, int j) {
  const Joint& joint = skeleton.joint(j);
  std::vector<Channel> source = DefaultChannels(false);
  if (!joint.bvh_channels.empty()) {
    ASSIGN_OR_RETURN(source, SourceChannels(joint));
  }
  ASSIGN_OR_RETURN(const ChannelLayout source_layout, Layout(source, joint.name));
  std::vector<Channel> channels;
  if (TranslationVaries(clip, j)) channels = {Channel::kXposition, Channel::kYposition, Channel::kZposition};
  for (int axis : source_layout.order.axes) channels.push_back(static_cast<Channel>(3 + axis));
  return channels;
}

Result<JointExportPlan> PlanJoint(const Skeleton& skeleton, const MotionClip& clip, int j, bool bvh_layouts,
                                  BvhLayout kind) {
  const Joint& joint = skeleton.joint(j);
  std::vector<Channel> channels;
  if (kind == BvhLayout::kStandard) {
    ASSIGN_OR_RETURN(channels, StandardChannels(skeleton, clip, j));
  } else if (bvh_layouts || !joint.bvh_channels.empty()) {
    ASSIGN_OR_RETURN(channels, SourceChannels(joint));
  } else {
    channels = DefaultChannels(joint.parent == kNoParent || (clip.translation_animated[j] != 0));
  }
  ASSIGN_OR_RETURN(ChannelLayout layout, Layout(channels, joint.name));
  ASSIGN_OR_RETURN(layout, Layout(WithNeededPositions(clip, j, layout), joint.name));

  JointExportPlan plan;
  plan.angles_deg = EulerTrack(clip, j, layout.order);
  if (layout.num_rotations < 3 && !UnlistedAnglesVanish(plan.angles_deg, layout.num_rotations)) {
    // The motion turns about an axis the source never listed: list the missing axes in the
    // order the angles were computed in, so the layout's order stays the same.
    std::vector<Channel> widened = layout.channels;
    for (int i = layout.num_rotations; i < 3; ++i) widened.push_back(static_cast<Channel>(3 + layout.order.axes[i]));
    ASSIGN_OR_RETURN(layout, Layout(widened, joint.name));
  }
  plan.layout = layout;
  for (Channel c : layout.channels) {
    int index = -1;
    for (int i = 0; i < 3 && IsRotation(c); ++i)
      if (layout.order.axes[i] == ChannelAxis(c)) index = i;
    plan.angle_index.push_back(index);
  }
  if (joint.parent != kNoParent) plan.parent_scale = skeleton.joint(joint.parent).rest_scale;
  // A standard layout's position channels hold the whole translation, over a zero OFFSET.
  Eigen::Vector3d base = kind == BvhLayout::kStandard ? Eigen::Vector3d::Zero()
                                                      : joint.bvh_offset.value_or(joint.rest_translation);
  for (int axis = 0; axis < 3; ++axis)
    if (layout.position_slot[axis] < 0) base[axis] = clip.translation(0, j)[axis];
  plan.offset_m = plan.parent_scale.cwiseProduct(base);
  return plan;
}

}  // namespace

Result<std::vector<JointExportPlan>> PlanBvhExport(const Skeleton& skeleton, const MotionClip& clip,
                                                   bool bvh_layouts, BvhLayout kind) {
  std::vector<JointExportPlan> plans;
  plans.reserve(skeleton.num_joints());
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    ASSIGN_OR_RETURN(JointExportPlan plan, PlanJoint(skeleton, clip, j, bvh_layouts, kind));
    plans.push_back(std::move(plan));
  }
  return plans;
}

}  // namespace mocapfill::bvh
