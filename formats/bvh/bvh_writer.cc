#include "formats/bvh/bvh_writer.h"

#include <charconv>
#include <cmath>
#include <utility>
#include <vector>

#include "formats/bvh/bvh_common.h"
#include "formats/bvh/bvh_export_plan.h"
#include "formats/units_axes.h"

namespace mocapfill {

namespace {

// Significant digits: enough that numbers read from a BVH text come back as written
// (15.735699999999998 prints as 15.7357), and that other sources lose at most ~1e-9
// relative (translations carry more digits: their error adds up along the chain).
constexpr int kAngleDigits = 10;
constexpr int kLengthDigits = 12;

void AppendNumber(std::string& out, double value, int digits) {
  char buffer[40];
  value += 0.0;  // -0 prints as 0
  const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, digits);
  out.append(buffer, result.ptr);
}

Result<double> OutputUnitScale(const Scene& scene, const ExportOptions& options) {
  if (options.unit == "auto") {
    const double scale = scene.source.unit_scale_to_m;
    return std::isfinite(scale) && scale > 0.0 ? scale : 1.0;
  }
  const std::optional<double> scale = UnitScaleByName(options.unit);
  if (!scale) return InvalidArgument("unknown BVH output unit '" + options.unit + "' (expected auto, m, cm, mm, in, ft or cmu)");
  return *scale;
}

// The source's own Frame Time text when it still reads back as the clip's rate.
std::string FrameTimeText(const Scene& scene, const MotionClip& clip) {
  const std::string& text = scene.source.source_frame_time_text;
  if (!text.empty() && text.size() < 32) {
    const char* begin = text.data() + (text[0] == '+' ? 1 : 0);
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(begin, text.data() + text.size(), value);
    if (ec == std::errc() && ptr == text.data() + text.size() && value > 0.0 && std::isfinite(value) &&
        bvh::SnapFrameRate(value) == clip.sample_rate_hz)
      return text;
  }
  return bvh::FormatFrameTime(clip.sample_rate_hz);
}

Status CheckNames(const Skeleton& skeleton) {
  for (const Joint& joint : skeleton.joints())
    if (joint.name.find_first_of("\r\n") != std::string::npos)
      return InvalidData("joint name '" + joint.name + "' contains a line break, which BVH cannot hold");
  return OkStatus();
}

class HierarchyWriter {
 public:
  HierarchyWriter(const Skeleton& skeleton, const std::vector<bvh::JointExportPlan>& plans, double unit_scale,
                  std::string& out)
      : skeleton_(skeleton), plans_(plans), inverse_unit_(1.0 / unit_scale), out_(out), children_(skeleton.num_joints()) {
    for (int j = 0; j < skeleton.num_joints(); ++j)
      if (skeleton.parent(j) != kNoParent) children_[skeleton.parent(j)].push_back(j);
  }

  // Writes the HIERARCHY section; returns the joints in the order their channels appear.
  std::vector<int> Write() {
    out_ += "HIERARCHY\n";
    // Iterative depth-first walk: (joint, next child), so deep chains cannot overflow the stack.
    for (int root : skeleton_.Roots()) {
      std::vector<std::pair<int, size_t>> stack;
      Open(root, 0);
      stack.emplace_back(root, 0);
      while (!stack.empty()) {
        auto& [joint, next] = stack.back();
        if (next < children_[joint].size()) {
          const int child = children_[joint][next++];
          Open(child, stack.size());
          stack.emplace_back(child, 0);
        } else {
          Close(joint, stack.size() - 1);
          stack.pop_back();
        }
      }
    }
    return order_;
  }

 private:
  void Indent(size_t depth) { out_.append(depth, '\t'); }

  void AppendVector(const Eigen::Vector3d& v) {
    for (int a = 0; a < 3; ++a) {
      out_ += ' ';
      AppendNumber(out_, v[a] * inverse_unit_, kLengthDigits);
    }
    out_ += '\n';
  }

  void Open(int j, size_t depth) {
    order_.push_back(j);
    Indent(depth);
    out_ += skeleton_.parent(j) == kNoParent ? "ROOT " : "JOINT ";
    out_ += skeleton_.name(j);
    out_ += '\n';
    Indent(depth);
    out_ += "{\n";
    Indent(depth + 1);
    out_ += "OFFSET";
    AppendVector(plans_[j].offset_m);
    Indent(depth + 1);
    out_ += "CHANNELS ";
    out_ += std::to_string(plans_[j].layout.channels.size());
    for (bvh::Channel c : plans_[j].layout.channels) {
      out_ += ' ';
      out_ += bvh::ChannelName(c);
    }
    out_ += '\n';
  }

  // A leaf without a stored End Site gets a zero-length one: readers expect every branch to end in one.
  void Close(int j, size_t depth) {
    const Joint& joint = skeleton_.joint(j);
    if (joint.end_site || children_[j].empty()) {
      const Eigen::Vector3d end = joint.rest_scale.cwiseProduct(joint.end_site.value_or(Eigen::Vector3d::Zero()));
      Indent(depth + 1);
      out_ += "End Site\n";
      Indent(depth + 1);
      out_ += "{\n";
      Indent(depth + 2);
      out_ += "OFFSET";
      AppendVector(end);
      Indent(depth + 1);
      out_ += "}\n";
    }
    Indent(depth);
    out_ += "}\n";
  }

  const Skeleton& skeleton_;
  const std::vector<bvh::JointExportPlan>& plans_;
  double inverse_unit_;
  std::string& out_;
  std::vector<std::vector<int>> children_;
  std::vector<int> order_;
};

void WriteFrames(const MotionClip& clip, const std::vector<bvh::JointExportPlan>& plans, const std::vector<int>& order,
                 double unit_scale, std::string& out) {
  const double inverse_unit = 1.0 / unit_scale;
  for (int f = 0; f < clip.num_frames; ++f) {
    bool first = true;
    for (int j : order) {
      const bvh::JointExportPlan& plan = plans[j];
      const Eigen::Vector3d t = plan.parent_scale.cwiseProduct(clip.translation(f, j)) * inverse_unit;
      for (size_t c = 0; c < plan.layout.channels.size(); ++c) {
        if (!first) out += ' ';
        first = false;
        const bvh::Channel channel = plan.layout.channels[c];
        if (bvh::IsRotation(channel)) {
          AppendNumber(out, plan.angles_deg[f][plan.angle_index[c]], kAngleDigits);
        } else {
          AppendNumber(out, t[bvh::ChannelAxis(channel)], kLengthDigits);
        }
      }
    }
    out += '\n';
  }
}

}  // namespace

Result<std::string> WriteBvh(const Scene& scene, const ExportOptions& options) {
  ASSIGN_OR_RETURN(const double unit_scale, OutputUnitScale(scene, options));
  const Skeleton& skeleton = scene.skeleton;
  if (skeleton.num_joints() == 0) return InvalidData("the scene has no skeleton to write as BVH");
  RETURN_IF_ERROR(CheckNames(skeleton));
  // Only the first clip is written; a skeleton without clips is written as one rest-pose frame.
  MotionClip rest_pose;
  if (scene.clips.empty()) rest_pose = MotionClip::RestPose(skeleton, 1, 30.0);
  const MotionClip& clip = scene.clips.empty() ? rest_pose : scene.clips.front();
  RETURN_IF_ERROR(clip.Validate(skeleton));
  if (!clip.uniform())
    return InvalidArgument("clip '" + clip.name + "' has explicit (non-uniform) frame times; BVH holds uniformly "
                           "sampled frames only: write .glb/.gltf to keep the key times, or resample the clip to a "
                           "frame rate first");
  // A skeleton that came from BVH (directly, or through glTF extras) keeps every joint's
  // layout, including joints that had no channels; others get the default layout.
  bool bvh_layouts = scene.source.format == "bvh";
  for (const Joint& joint : skeleton.joints()) bvh_layouts = bvh_layouts || !joint.bvh_channels.empty();
  ASSIGN_OR_RETURN(std::vector<bvh::JointExportPlan> plans, bvh::PlanBvhExport(skeleton, clip, bvh_layouts, options.bvh_layout));
  size_t channels = 0;
  for (const auto& plan : plans) channels += plan.layout.channels.size();
  if (channels == 0) {
    // A file without channels has no motion rows and cannot be read back: use the default layout.
    ASSIGN_OR_RETURN(plans, bvh::PlanBvhExport(skeleton, clip, false));
    for (const auto& plan : plans) channels += plan.layout.channels.size();
  }

  std::string out;
  out.reserve(4096 + static_cast<size_t>(clip.num_frames) * channels * 10);
  const std::vector<int> order = HierarchyWriter(skeleton, plans, unit_scale, out).Write();
  out += "MOTION\nFrames: " + std::to_string(clip.num_frames) + "\nFrame Time: " + FrameTimeText(scene, clip) + "\n";
  WriteFrames(clip, plans, order, unit_scale, out);
  return out;
}

}  // namespace mocapfill
