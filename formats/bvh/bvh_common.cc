#include "formats/bvh/bvh_common.h"

#include <charconv>
#include <cmath>

#include "formats/bvh/bvh_lexer.h"

namespace mocapfill::bvh {

namespace {

const char* const kChannelNames[] = {"Xposition", "Yposition", "Zposition", "Xrotation", "Yrotation", "Zrotation"};

// Rates that are not integers but common in video and capture (NTSC family).
constexpr double kNtscNumerators[] = {24000.0, 30000.0, 48000.0, 60000.0, 120000.0, 240000.0};

// Axes appended to a partial rotation list: Z, X, Y (the Biovision default order).
constexpr int kFillAxes[] = {2, 0, 1};

bool NearRate(double raw_hz, double candidate_hz) {
  return candidate_hz > 0.0 && std::abs(raw_hz - candidate_hz) <= kFrameRateSnapTolerance * candidate_hz;
}

// Shortest decimal text that parses back to exactly `value`.
std::string ShortestText(double value, int precision = 0) {
  char buffer[64];
  const auto result = precision > 0
                          ? std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, precision)
                          : std::to_chars(buffer, buffer + sizeof(buffer), value);
  return std::string(buffer, result.ptr);
}

double ParseText(const std::string& text) {
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

}  // namespace

std::optional<Channel> ParseChannel(std::string_view name) {
  for (int c = 0; c < 6; ++c)
    if (EqualsIgnoreCase(name, kChannelNames[c])) return static_cast<Channel>(c);
  return std::nullopt;
}

const char* ChannelName(Channel channel) { return kChannelNames[static_cast<int>(channel)]; }

ChannelLayout MakeChannelLayout(const std::vector<Channel>& channels, int& duplicate_index) {
  ChannelLayout layout;
  layout.channels = channels;
  duplicate_index = -1;
  std::array<int, 3> position{-1, -1, -1}, rotation_by_axis{-1, -1, -1};
  std::array<int, 3> listed_axes{};
  for (int i = 0; i < static_cast<int>(channels.size()); ++i) {
    const int axis = ChannelAxis(channels[i]);
    int& slot = IsRotation(channels[i]) ? rotation_by_axis[axis] : position[axis];
    if (slot >= 0) {
      duplicate_index = i;
      return layout;
    }
    slot = i;
    if (IsRotation(channels[i])) listed_axes[layout.num_rotations++] = axis;
    else ++layout.num_positions;
  }
  int n = layout.num_rotations;
  for (int axis : kFillAxes)
    if (rotation_by_axis[axis] < 0) listed_axes[n++] = axis;
  layout.order.axes = listed_axes;
  for (int i = 0; i < 3; ++i) layout.rotation_slot[i] = rotation_by_axis[listed_axes[i]];
  layout.position_slot = position;
  return layout;
}

double SnapFrameRate(double frame_time_s) {
  const double raw_hz = 1.0 / frame_time_s;
  const double integer_hz = std::round(raw_hz);
  if (integer_hz >= 1.0 && NearRate(raw_hz, integer_hz)) return integer_hz;
  for (double numerator : kNtscNumerators)
    if (NearRate(raw_hz, numerator / 1001.0)) return numerator / 1001.0;
  return raw_hz;
}

std::string FormatFrameTime(double rate_hz) {
  const double frame_time_s = 1.0 / rate_hz;
  // Snapped rates survive nine significant digits; other rates need the exact double, and
  // 1 / (1 / r) may miss r by an ulp, so look at the neighbours for one that maps back.
  const std::string short_text = ShortestText(frame_time_s, 9);
  if (SnapFrameRate(ParseText(short_text)) == rate_hz) return short_text;
  double candidate = frame_time_s;
  for (int step = 0; step < 8; ++step, candidate = std::nextafter(candidate, 0.0))
    if (SnapFrameRate(candidate) == rate_hz) return ShortestText(candidate);
  candidate = frame_time_s;
  for (int step = 0; step < 8; ++step, candidate = std::nextafter(candidate, 1e300))
    if (SnapFrameRate(candidate) == rate_hz) return ShortestText(candidate);
  return ShortestText(frame_time_s);
}

}  // namespace mocapfill::bvh
