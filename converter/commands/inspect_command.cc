// mocapfill inspect: what a motion file holds (skeleton, clips, rate, units, channels),
// as text or as JSON.
#include <nlohmann/json.hpp>
#include <cstdio>
#include <iostream>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/exit_codes.h"
#include "converter/import_flags.h"
#include "formats/motion_io.h"

namespace mocapfill::cli {

namespace {

struct InspectArgs {
  std::string input;
  bool json = false;
  ImportOptions import;
};

int KeyedJointCount(const MotionClip& clip) {
  int keyed = 0;
  for (const JointKeys& k : clip.keys) keyed += k.empty() ? 0 : 1;
  return keyed;
}

nlohmann::ordered_json Describe(const Scene& scene) {
  nlohmann::ordered_json out;
  out["file"] = scene.source.path;
  out["format"] = scene.source.format;
  out["unit"] = {{"name", scene.source.unit_name},
                 {"metres_per_unit", scene.source.unit_scale_to_m},
                 {"detected", scene.source.unit_detected}};
  out["up_axis"] = scene.source.up_axis;
  if (!scene.source.source_frame_time_text.empty()) out["source_frame_time"] = scene.source.source_frame_time_text;
  if (scene.source.declared_frames >= 0) out["declared_frames"] = scene.source.declared_frames;
  const Skeleton& skeleton = scene.skeleton;
  nlohmann::ordered_json joints = nlohmann::ordered_json::array();
  int channels = 0;
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const Joint& joint = skeleton.joint(j);
    nlohmann::ordered_json entry;
    entry["name"] = joint.name;
    entry["parent"] = joint.parent == kNoParent ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(skeleton.name(joint.parent));
    entry["offset_m"] = {joint.rest_translation.x(), joint.rest_translation.y(), joint.rest_translation.z()};
    if (!joint.bvh_channels.empty()) entry["channels"] = joint.bvh_channels;
    channels += static_cast<int>(joint.bvh_channels.size());
    joints.push_back(entry);
  }
  out["skeleton"] = {{"joints", skeleton.num_joints()}, {"roots", skeleton.Roots().size()}, {"channels", channels}};
  out["joints"] = joints;
  nlohmann::ordered_json clips = nlohmann::ordered_json::array();
  for (const MotionClip& clip : scene.clips) {
    int animated_translations = 0;
    for (auto a : clip.translation_animated) animated_translations += a;
    clips.push_back({{"name", clip.name},
                     {"frames", clip.num_frames},
                     {"rate_hz", clip.sample_rate_hz},
                     {"duration_s", clip.duration_s()},
                     {"keyed_joints", KeyedJointCount(clip)},
                     {"translating_joints", animated_translations}});
  }
  out["clips"] = clips;
  out["meshes"] = scene.meshes.size();
  out["skins"] = scene.skins.size();
  out["warnings"] = scene.warnings;
  return out;
}

void PrintText(const Scene& scene) {
  const Skeleton& s = scene.skeleton;
  std::printf("file:      %s (%s)\n", scene.source.path.c_str(), scene.source.format.c_str());
  std::printf("units:     %s (%g m per unit%s), up axis %s\n", scene.source.unit_name.c_str(),
              scene.source.unit_scale_to_m, scene.source.unit_detected ? ", detected from skeleton height" : "",
              scene.source.up_axis.c_str());
  std::printf("skeleton:  %d joints, %zu root(s)\n", s.num_joints(), s.Roots().size());
  for (int j = 0; j < s.num_joints(); ++j) {
    int depth = 0;
    for (int p = s.parent(j); p != kNoParent; p = s.parent(p)) ++depth;
    std::string channels;
    for (const std::string& c : s.joint(j).bvh_channels) channels += (channels.empty() ? "" : " ") + c;
    std::printf("  %*s%s%s%s%s\n", 2 * depth, "", s.name(j).c_str(), channels.empty() ? "" : "  [",
                channels.c_str(), channels.empty() ? "" : "]");
  }
  for (const MotionClip& clip : scene.clips)
    std::printf("clip:      '%s' %d frames at %g Hz, %.4f s, %d of %d joints keyed\n", clip.name.c_str(),
                clip.num_frames, clip.sample_rate_hz, clip.duration_s(), KeyedJointCount(clip), clip.num_joints);
  if (!scene.meshes.empty()) std::printf("meshes:    %zu (%zu skins)\n", scene.meshes.size(), scene.skins.size());
  for (const std::string& w : scene.warnings) std::printf("warning:   %s\n", w.c_str());
}

int RunInspect(const InspectArgs& args) {
  Result<Scene> scene = ImportFile(args.input, args.import);
  if (!scene.ok()) {
    PrintError(scene.status().message());
    return ExitCodeFor(scene.status(), Stage::kInput);
  }
  if (args.json) {
    std::cout << Describe(*scene).dump(2) << "\n";
  } else {
    PrintText(*scene);
  }
  return kExitOk;
}

}  // namespace

void AddInspectCommand(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<InspectArgs>();
  CLI::App* command = app.add_subcommand("inspect", "Show skeleton, joints, frames, rate, duration, channels and units");
  command->add_option("input", args->input, "Input file (.bvh .gltf .glb .fbx)")->required();
  command->add_flag("--json", args->json, "Print a JSON report instead of text");
  AddImportFlags(*command, args->import);
  command->footer(
      "Examples:\n"
      "  mocapfill inspect walk.bvh\n"
      "  mocapfill inspect walk.glb --json | jq .clips");
  command->callback([args, &action] { action = [args] { return RunInspect(*args); }; });
}

}  // namespace mocapfill::cli
