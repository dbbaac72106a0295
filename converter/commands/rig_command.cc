// mocapfill rig show: how a rig maps to the canonical humanoid (naming family, bone per
// joint, missing bones), which rest pose is used and why, its proportions, the joints left
// unmapped and why; as text or JSON.
#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/exit_codes.h"
#include "converter/import_flags.h"
#include "formats/file_io.h"
#include "formats/motion_io.h"
#include "formats/name_map_json.h"
#include "processing/retargeting/proportions.h"
#include "processing/retargeting/rest_pose.h"
#include "processing/retargeting/rig_mapping.h"

namespace mocapfill::cli {

namespace {

struct RigShowArgs {
  std::string input;
  bool json = false;
  std::string map;  // inline JSON or a file
  std::string rest = "auto";
  ImportOptions import;
};

// The --map value: inline JSON when it starts with '{', else a file to read.
Result<std::map<std::string, std::string>> ReadMap(const std::string& value) {
  if (value.empty()) return std::map<std::string, std::string>{};
  return ReadNameMap(value, "--map", kRigMapShape);
}

struct RigReport {
  RigMapping mapping;
  RigRest rest;
  RigProportions proportions;
};

// Maps with the zero pose's layout, chooses the rest, and maps again with the rest pose when
// that is another pose (Bandai's zero pose shows no sides; its first frame does).
Result<RigReport> Analyse(const Scene& scene, const RigMapOptions& options, RestSource source) {
  const Skeleton& skeleton = scene.skeleton;
  ASSIGN_OR_RETURN(RigMapping first, MapHumanoid(skeleton, ZeroPose(skeleton).WorldPositions(skeleton), options));
  ASSIGN_OR_RETURN(RigRest rest, ChooseRest(scene, first, source));
  RigReport report{std::move(first), std::move(rest), {}};
  if (report.rest.source != RestSource::kZero) {
    ASSIGN_OR_RETURN(report.mapping, MapHumanoid(skeleton, report.rest.WorldPositions(skeleton), options));
  }
  report.proportions = MeasureProportions(skeleton, report.mapping, report.rest);
  return report;
}

nlohmann::ordered_json Describe(const Scene& scene, const RigReport& r) {
  const Skeleton& s = scene.skeleton;
  nlohmann::ordered_json out;
  out["file"] = scene.source.path;
  out["family"] = r.mapping.family;
  nlohmann::ordered_json bones = nlohmann::ordered_json::object();
  nlohmann::ordered_json missing = nlohmann::ordered_json::array();
  for (int i = 0; i < kNumHumanoidBones; ++i) {
    const int j = r.mapping.joints[i];
    bones[HumanoidBoneName(BoneAt(i))] = j >= 0 ? nlohmann::ordered_json(s.name(j)) : nlohmann::ordered_json(nullptr);
    if (j < 0) missing.push_back(HumanoidBoneName(BoneAt(i)));
  }
  out["bones"] = bones;
  out["missing_bones"] = missing;
  out["rest"] = {{"source", RestSourceName(r.rest.source)}, {"reason", r.rest.reason}};
  out["proportions_m"] = {{"hip_height", r.proportions.hip_height},
                          {"leg_length", r.proportions.leg_length},
                          {"arm_length", r.proportions.arm_length},
                          {"height", r.proportions.height}};
  nlohmann::ordered_json unmapped = nlohmann::ordered_json::array();
  for (int j = 0; j < s.num_joints(); ++j)
    if (r.mapping.BoneOfJoint(j) < 0) unmapped.push_back({{"joint", s.name(j)}, {"why", UnmappedJointReason(s, r.mapping, j)}});
  out["unmapped_joints"] = unmapped;
  out["notes"] = r.mapping.notes;
  out["warnings"] = r.mapping.warnings;
  return out;
}

void PrintText(const Scene& scene, const RigReport& r) {
  const Skeleton& s = scene.skeleton;
  std::printf("file:      %s\n", scene.source.path.c_str());
  std::printf("family:    %s\n", r.mapping.family.c_str());
  std::printf("bones:\n");
  std::string missing;
  for (int i = 0; i < kNumHumanoidBones; ++i) {
    const int j = r.mapping.joints[i];
    std::printf("  %-14s %s\n", HumanoidBoneName(BoneAt(i)), j >= 0 ? s.name(j).c_str() : "\xE2\x80\x94");
    if (j < 0) missing += std::string(missing.empty() ? "" : ", ") + HumanoidBoneName(BoneAt(i));
  }
  // Errors stop before this point when a required bone is missing: what is left is optional.
  std::printf("missing:   %s\n", missing.empty() ? "none" : (missing + " (optional; every required bone is present)").c_str());
  std::printf("rest:      %s: %s\n", RestSourceName(r.rest.source), r.rest.reason.c_str());
  std::printf("proportions (m): hip height %.3f, leg length %.3f, arm length %.3f, height %.3f\n",
              r.proportions.hip_height, r.proportions.leg_length, r.proportions.arm_length, r.proportions.height);
  std::printf("unmapped joints:\n");
  for (int j = 0; j < s.num_joints(); ++j)
    if (r.mapping.BoneOfJoint(j) < 0) std::printf("  %s: %s\n", s.name(j).c_str(), UnmappedJointReason(s, r.mapping, j).c_str());
  for (const std::string& n : r.mapping.notes) std::printf("note:      %s\n", n.c_str());
  for (const std::string& w : r.mapping.warnings) std::printf("warning:   %s\n", w.c_str());
}

int RunRigShow(const RigShowArgs& args) {
  Result<RestSource> source = ParseRestSource(args.rest);
  if (!source.ok()) {
    PrintError(source.status().message());
    return kExitUsage;
  }
  Result<std::map<std::string, std::string>> map = ReadMap(args.map);
  if (!map.ok()) {
    PrintError(map.status().message());
    return ExitCodeFor(map.status(), Stage::kInput);
  }
  Result<Scene> scene = ImportFile(args.input, args.import);
  if (!scene.ok()) {
    PrintError(scene.status().message());
    return ExitCodeFor(scene.status(), Stage::kInput);
  }
  RigMapOptions options;
  options.overrides = *map;
  Result<RigReport> report = Analyse(*scene, options, *source);
  if (!report.ok()) {
    PrintError(report.status().WithContext(args.input).message());
    return ExitCodeFor(report.status(), Stage::kInput);
  }
  if (args.json) {
    std::cout << Describe(*scene, *report).dump(2) << "\n";
  } else {
    PrintText(*scene, *report);
  }
  return kExitOk;
}

}  // namespace

void AddRigCommand(CLI::App& app, CommandAction& action) {
  CLI::App* rig = app.add_subcommand("rig", "Describe how a rig maps to the canonical humanoid");
  rig->require_subcommand(1);
  auto args = std::make_shared<RigShowArgs>();
  CLI::App* show = rig->add_subcommand("show", "Humanoid bones, rest pose, proportions and unmapped joints of a rig");
  show->add_option("input", args->input, "Input file (.bvh .gltf .glb .fbx)")->required();
  show->add_flag("--json", args->json, "Print a JSON report instead of text");
  show->add_option("--map", args->map, "Rig map: inline JSON {\"joint\": \"bone\"} or a JSON file");
  show->add_option("--rest", args->rest, "Rest pose: auto, bind, zero, mean or first-frame")
      ->check(CLI::IsMember(RestSourceNames()))
      ->default_str("auto");
  AddImportFlags(*show, args->import);
  show->footer(
      "Examples:\n"
      "  mocapfill rig show walk.bvh\n"
      "  mocapfill rig show Geno.fbx --json | jq .bones\n"
      "  mocapfill rig show boxing.bvh --map '{\"LeftCollar\": \"\"}' --rest first-frame");
  show->callback([args, &action] { action = [args] { return RunRigShow(*args); }; });
}

}  // namespace mocapfill::cli
