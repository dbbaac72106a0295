#include "formats/bvh/bvh_hierarchy.h"

#include <unordered_map>

#include "processing/core/skeleton.h"

namespace mocapfill::bvh {

namespace {

// A joint row can hold at most the six distinct channels.
constexpr int64_t kMaxChannelsPerJoint = 6;

bool IsKeyword(std::string_view token) {
  for (const char* keyword : {"ROOT", "JOINT", "OFFSET", "CHANNELS", "End", "MOTION", "HIERARCHY", "{", "}"})
    if (EqualsIgnoreCase(token, keyword)) return true;
  return false;
}

std::string Quoted(std::string_view text) { return BvhLexer::Quote(text); }

class HierarchyParser {
 public:
  explicit HierarchyParser(BvhLexer& lexer) : lexer_(lexer) {}

  Result<ParsedHierarchy> Parse() {
    std::string_view token = lexer_.NextToken();
    if (!EqualsIgnoreCase(token, "HIERARCHY"))
      return Error("expected 'HIERARCHY' at the start of a BVH file, got " + Describe(token));
    while (true) {
      token = lexer_.NextToken();
      if (open_.empty()) {
        if (EqualsIgnoreCase(token, "MOTION")) break;
        if (!EqualsIgnoreCase(token, "ROOT")) return Error("expected ROOT or MOTION, got " + Describe(token));
        RETURN_IF_ERROR(OpenJoint(-1, "ROOT"));
      } else {
        RETURN_IF_ERROR(JointStatement(token));
      }
    }
    if (result_.joints.empty()) return Error("MOTION before any ROOT: the file has no skeleton");
    return std::move(result_);
  }

 private:
  std::string Describe(std::string_view token) const {
    return token.empty() ? std::string("the end of the file") : Quoted(token);
  }
  Status Error(const std::string& message) const { return lexer_.ErrorAt(lexer_.token_location(), message); }
  ParsedJoint& Current() { return result_.joints[open_.back().index]; }

  // One statement inside the innermost open joint.
  Status JointStatement(std::string_view token) {
    if (EqualsIgnoreCase(token, "OFFSET")) return ReadJointOffset();
    if (EqualsIgnoreCase(token, "CHANNELS")) return ReadChannels();
    if (EqualsIgnoreCase(token, "JOINT")) return OpenJoint(open_.back().index, "JOINT");
    if (EqualsIgnoreCase(token, "End")) return ReadEndSite();
    if (token == "}") return CloseJoint();
    const ParsedJoint& joint = Current();
    if (token.empty() || EqualsIgnoreCase(token, "MOTION") || EqualsIgnoreCase(token, "ROOT"))
      return Error("expected '}' to close joint " + Quoted(joint.name) + " (opened at line " +
                   std::to_string(joint.location.line) + "), got " + Describe(token));
    if (ParseChannel(token))
      return Error("channel name " + Quoted(token) + " after the CHANNELS list of joint " + Quoted(joint.name) +
                   ": the CHANNELS count is smaller than the number of names");
    return Error("expected OFFSET, CHANNELS, JOINT, End Site or '}' in joint " + Quoted(joint.name) + ", got " +
                 Describe(token));
  }

  Status OpenJoint(int parent, const char* keyword) {
    const TextLocation keyword_location = lexer_.token_location();
    std::string_view name = lexer_.RestOfLine();
    // Tolerate "JOINT Spine {" on one line; a name is otherwise the whole rest of the line.
    bool brace_on_line = false;
    if (name.size() >= 1 && name.back() == '{' &&
        (name.size() == 1 || name[name.size() - 2] == ' ' || name[name.size() - 2] == '\t')) {
      brace_on_line = true;
      name.remove_suffix(1);
      while (!name.empty() && (name.back() == ' ' || name.back() == '\t')) name.remove_suffix(1);
    }
    if (name.empty())
      return lexer_.ErrorAt(lexer_.Here(), std::string("expected a joint name after ") + keyword);
    if (result_.joints.size() >= static_cast<size_t>(kMaxSkeletonJoints))
      return Error("more than " + std::to_string(kMaxSkeletonJoints) + " joints: not a character rig");
    const auto [it, inserted] = name_lines_.emplace(std::string(name), keyword_location.line);
    if (!inserted)
      return lexer_.ErrorAt(keyword_location, "duplicate joint name " + Quoted(name) + " (first defined at line " +
                                                  std::to_string(it->second) + ")");
    if (!brace_on_line) {
      const std::string_view brace = lexer_.NextToken();
      if (brace != "{") return Error("expected '{' after joint " + Quoted(name) + ", got " + Describe(brace));
    }
    ParsedJoint joint;
    joint.name = std::string(name);
    joint.parent = parent;
    joint.location = keyword_location;
    result_.joints.push_back(std::move(joint));
    open_.push_back({static_cast<int>(result_.joints.size()) - 1});
    return OkStatus();
  }

  Status CloseJoint() {
    const OpenJointState state = open_.back();
    if (!state.has_offset) {
      const ParsedJoint& joint = result_.joints[state.index];
      return lexer_.ErrorAt(joint.location, "joint " + Quoted(joint.name) + " has no OFFSET");
    }
    open_.pop_back();
    return OkStatus();
  }

  Status ReadVector(Eigen::Vector3d& out, const std::string& what) {
    static const char* const kAxes[] = {"X", "Y", "Z"};
    for (int axis = 0; axis < 3; ++axis) {
      ASSIGN_OR_RETURN(out[axis], lexer_.NextNumber(std::string("the ") + kAxes[axis] + " " + what));
    }
    return OkStatus();
  }

  Status ReadJointOffset() {
    if (open_.back().has_offset) return Error("second OFFSET in joint " + Quoted(Current().name));
    open_.back().has_offset = true;
    return ReadVector(Current().offset, "offset of joint " + Quoted(Current().name));
  }

  Status ReadChannels() {
    if (open_.back().has_channels) return Error("second CHANNELS line in joint " + Quoted(Current().name));
    open_.back().has_channels = true;
    const std::string joint_name = Quoted(Current().name);
    ASSIGN_OR_RETURN(const int64_t count,
                     lexer_.NextCount("the CHANNELS count of joint " + joint_name, kMaxChannelsPerJoint));
    std::vector<Channel> channels;
    for (int64_t i = 0; i < count; ++i) {
      const std::string_view token = lexer_.NextToken();
      const std::optional<Channel> channel = ParseChannel(token);
      if (!channel) {
        if (token.empty() || IsKeyword(token))
          return Error("CHANNELS of joint " + joint_name + " declares " + std::to_string(count) + " channels but lists " +
                       std::to_string(i) + " before " + Describe(token));
        return Error("unknown channel " + Quoted(token) +
                     " (expected Xposition, Yposition, Zposition, Xrotation, Yrotation or Zrotation)");
      }
      channels.push_back(*channel);
      int duplicate = -1;
      MakeChannelLayout(channels, duplicate);
      if (duplicate >= 0) return Error("channel " + Quoted(token) + " is listed twice for joint " + joint_name);
    }
    int duplicate = -1;
    Current().layout = MakeChannelLayout(channels, duplicate);
    Current().first_channel = result_.num_channels;
    result_.num_channels += static_cast<int>(count);
    return OkStatus();
  }

  Status ReadEndSite() {
    const TextLocation end_location = lexer_.token_location();
    const std::string_view site = lexer_.NextToken();
    if (!EqualsIgnoreCase(site, "Site")) return Error("expected 'Site' after 'End', got " + Describe(site));
    const std::string owner = Quoted(Current().name);
    std::string_view token = lexer_.NextToken();
    if (token != "{") return Error("expected '{' after End Site of joint " + owner + ", got " + Describe(token));
    token = lexer_.NextToken();
    if (!EqualsIgnoreCase(token, "OFFSET"))
      return Error("expected OFFSET in the End Site of joint " + owner + ", got " + Describe(token));
    Eigen::Vector3d offset;
    RETURN_IF_ERROR(ReadVector(offset, "offset of the End Site of joint " + owner));
    token = lexer_.NextToken();
    if (token != "}") return Error("expected '}' to close the End Site of joint " + owner + ", got " + Describe(token));
    if (Current().end_site) {
      result_.warnings.push_back(lexer_.path() + ":" + std::to_string(end_location.line) + ":" +
                                 std::to_string(end_location.column) + ": joint " + owner +
                                 " has a second End Site; only the first is kept");
    } else {
      Current().end_site = offset;
    }
    return OkStatus();
  }

  struct OpenJointState {
    int index = 0;
    bool has_offset = false;
    bool has_channels = false;
  };

  BvhLexer& lexer_;
  ParsedHierarchy result_;
  std::vector<OpenJointState> open_;  // explicit stack: deep nesting cannot overflow the call stack
  std::unordered_map<std::string, int64_t> name_lines_;
};

}  // namespace

Result<ParsedHierarchy> ParseHierarchy(BvhLexer& lexer) { return HierarchyParser(lexer).Parse(); }

}  // namespace mocapfill::bvh
