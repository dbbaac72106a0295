#include "formats/bvh/bvh_motion.h"

#include <algorithm>
#include <cstring>
#include <array>
#include <charconv>
#include <climits>
#include <cstddef>
#include <vector>

#include "formats/bvh/bvh_euler.h"
#include "formats/bvh/bvh_motion_rows.h"
#include "formats/bvh/bvh_number.h"
#include "processing/core/rotation.h"

namespace mocapfill::bvh {

namespace rows {

std::vector<JointSampler> MakeSamplers(const ParsedHierarchy& hierarchy) {
  std::vector<JointSampler> samplers;
  samplers.reserve(hierarchy.joints.size());
  for (const ParsedJoint& joint : hierarchy.joints) {
    JointSampler s;
    for (int i = 0; i < 3; ++i) {
      if (joint.layout.rotation_slot[i] >= 0) s.rotation_index[i] = joint.first_channel + joint.layout.rotation_slot[i];
      if (joint.layout.position_slot[i] >= 0) s.position_index[i] = joint.first_channel + joint.layout.position_slot[i];
    }
    s.num_rotations = joint.layout.num_rotations;
    s.compose = HalfAngleComposerFor(joint.layout.order);
    s.offset = joint.offset;
    samplers.push_back(s);
  }
  return samplers;
}

std::vector<ChannelGroup> MakeChannelGroups(const ParsedHierarchy& hierarchy) {
  std::vector<ChannelGroup> groups;
  for (const ParsedJoint& joint : hierarchy.joints) {
    const std::vector<Channel>& channels = joint.layout.channels;
    for (size_t i = 0; i < channels.size(); ++i) {
      const int channel = joint.first_channel + static_cast<int>(i);
      if (i > 0 && IsRotation(channels[i]) == IsRotation(channels[i - 1]))
        ++groups.back().count;
      else
        groups.push_back({channel, 1});
    }
  }
  return groups;
}

}  // namespace rows

namespace {

using rows::RowEnd;
using rows::kMaxJointFrames;

std::string FrameCounts(int64_t frame, const MotionHeader& header) {
  return "frame " + std::to_string(frame) + " (0-based; " + std::to_string(frame) + " complete of " +
         std::to_string(header.declared_frames) + " declared)";
}

[[gnu::cold]] Status RowEndsEarly(const BvhLexer& lexer, int64_t frame, int values, int expected,
                                  const MotionHeader& header) {
  if (lexer.AtEnd())
    return lexer.ErrorAt(lexer.Here(), "the motion data is truncated in " + FrameCounts(frame, header) + ": the row has " +
                                           std::to_string(values) + " of " + std::to_string(expected) + " values");
  return lexer.ErrorAt(lexer.Here(), "frame " + std::to_string(frame) + " has " + std::to_string(values) +
                                         " values, expected " + std::to_string(expected) +
                                         " (one row per frame, one value per channel)");
}

[[gnu::cold]] Status BadValue(const BvhLexer& lexer, int64_t frame) {
  // Tell "nan"/"inf" (parsed, but not finite) apart from text that is no number at all.
  std::string_view rest = lexer.TextFromHere();
  size_t length = 0;
  while (length < rest.size() && rest[length] != ' ' && rest[length] != '\t' && rest[length] != '\n' &&
         rest[length] != '\r')
    ++length;
  const char* begin = rest.data() + (length > 0 && rest[0] == '+' ? 1 : 0);
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(begin, rest.data() + length, value);
  const bool non_finite = ec == std::errc() && ptr == rest.data() + length;
  const bool out_of_range = ec == std::errc::result_out_of_range;
  const std::string token = lexer.QuoteTokenAt(lexer.position());
  const std::string where = " in frame " + std::to_string(frame);
  if (out_of_range) return lexer.ErrorAt(lexer.Here(), "number " + token + " is out of range" + where);
  return lexer.ErrorAt(lexer.Here(), (non_finite ? "expected a finite number, got " : "expected a number, got ") +
                                         token + where);
}

[[gnu::cold]] Status RowTooLong(const BvhLexer& lexer, int64_t frame, int expected) {
  return lexer.ErrorAt(lexer.Here(), "frame " + std::to_string(frame) + " has more than " + std::to_string(expected) +
                                         " values: unexpected " + lexer.QuoteTokenAt(lexer.position()));
}

// Reads "Frames:" or "Frames" ":", and "Frame Time:" split across tokens in any of the
// ways files write it.
Status ExpectLabel(BvhLexer& lexer, std::string_view word, const char* label) {
  const std::string_view token = lexer.NextToken();
  if (EqualsIgnoreCase(token, std::string(word) + ":")) return OkStatus();
  if (EqualsIgnoreCase(token, word)) {
    const std::string_view colon = lexer.NextToken();
    if (colon == ":") return OkStatus();
  }
  return lexer.ErrorAt(lexer.token_location(), std::string("expected '") + label + "', got " +
                                                   (token.empty() ? std::string("the end of the file")
                                                                  : BvhLexer::Quote(token)));
}

// Lines from `p` to `end`, counted no further than `cap` (so that only the text that many rows
// take is read).
size_t LinesUpTo(const char* p, const char* end, size_t cap) {
  size_t lines = 1;
  while (lines < cap && p < end) {
    p = static_cast<const char*>(std::memchr(p, '\n', static_cast<size_t>(end - p)));
    if (p == nullptr) break;
    ++p;
    ++lines;
  }
  return std::min(lines, cap);
}

}  // namespace

Result<MotionHeader> ParseMotionHeader(BvhLexer& lexer) {
  MotionHeader header;
  RETURN_IF_ERROR(ExpectLabel(lexer, "Frames", "Frames:"));
  ASSIGN_OR_RETURN(header.declared_frames, lexer.NextCount("the Frames count", INT_MAX));
  header.frames_location = lexer.token_location();
  const std::string_view frame = lexer.NextToken();
  if (!EqualsIgnoreCase(frame, "Frame"))
    return lexer.ErrorAt(lexer.token_location(), "expected 'Frame Time:', got " +
                                                     (frame.empty() ? std::string("the end of the file")
                                                                    : BvhLexer::Quote(frame)));
  RETURN_IF_ERROR(ExpectLabel(lexer, "Time", "Frame Time:"));
  ASSIGN_OR_RETURN(header.frame_time_s, lexer.NextNumber("the Frame Time"));
  header.frame_time_text = std::string(lexer.last_token());
  if (!(header.frame_time_s > 0.0))
    return lexer.ErrorAt(lexer.token_location(), "the Frame Time must be positive, got " +
                                                     BvhLexer::Quote(header.frame_time_text));
  lexer.SkipBlanks();
  if (!lexer.AtLineEnd())
    return lexer.ErrorAt(lexer.Here(), "unexpected " + lexer.QuoteTokenAt(lexer.position()) +
                                           " after the Frame Time (frame rows start on the next line)");
  return header;
}

Status ParseMotionRows(BvhLexer& lexer, const ParsedHierarchy& hierarchy, const MotionHeader& header,
                       MotionClip& clip, MotionRowsParser parse_rows) {
  const int channels = hierarchy.num_channels;
  const std::vector<rows::JointSampler> samplers = rows::MakeSamplers(hierarchy);
  const std::vector<rows::ChannelGroup> groups = rows::MakeChannelGroups(hierarchy);
  const size_t joints = samplers.size();
  clip.num_joints = static_cast<int>(joints);
  // Every value takes at least two bytes: the rest of the file holds at most this many rows.
  const size_t max_rows = lexer.remaining_bytes() / (2 * static_cast<size_t>(channels)) + 1;
  // A motion declared past the limit, in a file large enough to hold it, is refused before
  // any row is read or any memory reserved for it.
  if (std::min(static_cast<size_t>(header.declared_frames), max_rows) * joints > kMaxJointFrames)
    return lexer.ErrorAt(lexer.Here(), "the motion is too large: Frames declares " +
                                           std::to_string(header.declared_frames) + " frames of " + std::to_string(joints) +
                                           " joints, more than the " + std::to_string(kMaxJointFrames) +
                                           " joint-frames mocapfill reads");
  if (parse_rows != nullptr) {
    if (parse_rows(lexer.TextFromHere(), samplers, groups, channels, header.declared_frames, clip)) return OkStatus();
    clip.rotations.clear();
    clip.translations.clear();
  }
  // Reserve for the rows the rest of the file holds (each ends its line; counting lines costs a
  // small part of parsing them), never past the limit: "Frames: 1000000000" over ten rows
  // reserves ten, and "Frames: 1" over a gigabyte of rows does not grow by doubling past it.
  const size_t cap = std::min(max_rows, kMaxJointFrames / joints);
  const size_t reserve_rows = LinesUpTo(lexer.cursor(), lexer.text_end(), cap);
  clip.rotations.reserve(reserve_rows * joints);
  clip.translations.reserve(reserve_rows * joints);

  std::vector<double> row(channels);
  rows::FrameComposer composer(samplers, groups);
  rows::RowScanner scanner(groups, channels);
  int64_t frame = 0;
  while (true) {
    lexer.SkipWhitespace();  // line breaks and blank lines between rows
    if (lexer.AtEnd()) break;
    if (static_cast<size_t>(frame + 1) * joints > kMaxJointFrames)
      return lexer.ErrorAt(lexer.Here(), "the motion is too large: more than " + std::to_string(frame) +
                                             " frames of " + std::to_string(joints) + " joints");
    const char* p = lexer.cursor();
    const RowEnd end = scanner.Scan(p, lexer.text_end(), row.data());
    lexer.MoveWithinLine(p);
    switch (end.kind) {
      case RowEnd::kComplete:
        break;
      case RowEnd::kShort:
        return RowEndsEarly(lexer, frame, end.values, channels, header);
      case RowEnd::kBadValue:
        return BadValue(lexer, frame);
      case RowEnd::kLong:
        return RowTooLong(lexer, frame, channels);
    }
    const size_t base = clip.rotations.size();
    clip.rotations.resize(base + joints);  // Eigen's constructors leave the new entries alone
    clip.translations.resize(base + joints);
    composer.Compose(scanner, row.data(), base >= joints ? &clip.rotations[base - joints] : nullptr, &clip.rotations[base],
                     &clip.translations[base]);
    ++frame;
  }
  clip.num_frames = static_cast<int>(frame);
  return OkStatus();
}

}  // namespace mocapfill::bvh
