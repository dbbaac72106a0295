// Vocabulary shared by the BVH reader and writer: channel names and how a joint's
// channels map to a translation and an Euler rotation, and Frame Time <-> frame rate.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "processing/core/rotation.h"

namespace mocapfill::bvh {

// The six BVH channels. Values 0-2 are positions along X/Y/Z, 3-5 rotations about X/Y/Z.
enum class Channel : std::uint8_t { kXposition, kYposition, kZposition, kXrotation, kYrotation, kZrotation };

// Parses "Xposition" ... "Zrotation" (case-insensitive), or nullopt.
std::optional<Channel> ParseChannel(std::string_view name);
// The canonical spelling ("Zrotation").
const char* ChannelName(Channel channel);
inline bool IsRotation(Channel c) { return static_cast<int>(c) >= 3; }
inline int ChannelAxis(Channel c) { return static_cast<int>(c) % 3; }

// One joint's channels in listed order, and where each component sits among them.
struct ChannelLayout {
  std::vector<Channel> channels;
  // Rotation order: the rotation channels in listed order (intrinsic composition), then
  // any unlisted axes (preferring Z, X, Y), whose angle is zero.
  EulerOrder order;
  int num_rotations = 0;
  // Index into `channels` of the angle about order.axes[i], or -1 when not listed.
  std::array<int, 3> rotation_slot{-1, -1, -1};
  // Index into `channels` of the X/Y/Z position, or -1 when not listed.
  std::array<int, 3> position_slot{-1, -1, -1};
  int num_positions = 0;
};

// Builds the layout of a channel list; returns the index of the first repeated channel in
// `duplicate_index` (and an incomplete layout) when a channel is listed twice, else -1.
ChannelLayout MakeChannelLayout(const std::vector<Channel>& channels, int& duplicate_index);

// The frame rate (Hz) for a BVH Frame Time (s). Frame Time is usually a rounded text
// ("0.0333333", ".0083333"), so a rate within kFrameRateSnapTolerance (relative) of an
// integer or of an NTSC rate (24000/1001, 30000/1001, ...) is snapped to it exactly.
// Requires frame_time_s > 0.
double SnapFrameRate(double frame_time_s);
constexpr double kFrameRateSnapTolerance = 1e-4;

// Frame Time text for a rate, short and such that SnapFrameRate(parse(text)) == rate_hz
// ("0.0333333333" for 30 Hz).
std::string FormatFrameTime(double rate_hz);

}  // namespace mocapfill::bvh
