// mocapfill filter: multiresolution filtering (Bruderlin-Williams band gains) of a motion
// file, written through the exporters (validator-clean glTF, or BVH).
#include <cstdio>
#include <filesystem>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/database_arg.h"
#include "converter/exit_codes.h"
#include "converter/export_flags.h"
#include "converter/import_flags.h"
#include "formats/file_io.h"
#include "formats/motion_io.h"
#include "processing/filtering/motion_filter.h"

namespace mocapfill::cli {

namespace {

namespace fs = std::filesystem;

struct FilterArgs {
  std::string input;
  std::string output;
  std::vector<double> gains;
  std::vector<std::string> joints;
  int levels = 0;
  double residual_gain = 1.0;
  bool periodic = false;
  std::string db;
  ImportOptions import;
  ExportOptions export_options;
};

// The database's joint means re-indexed for the clip's skeleton, so filtering happens about
// the database's reference. Fails naming a joint the database lacks.
Result<TangentReference> ReferenceFor(const Skeleton& skeleton, const MotionDatabase& db) {
  TangentReference reference;
  for (int j = 0; j < skeleton.num_joints(); ++j) {
    const std::optional<int> d = db.skeleton().Find(skeleton.name(j));
    if (!d) return InvalidData("joint '" + skeleton.name(j) + "' is not in the database skeleton");
    reference.joint_means.push_back(db.joint_means()[*d]);
    if (*d == db.root_joint()) reference.root_joint = j;
  }
  return reference;
}

Result<std::vector<int>> JointIndices(const Skeleton& skeleton, const std::vector<std::string>& names) {
  std::vector<int> indices;
  for (const std::string& name : names) {
    const std::optional<int> j = skeleton.Find(name);
    if (!j) return InvalidArgument("--joints: no joint named '" + name + "' in the input skeleton");
    indices.push_back(*j);
  }
  return indices;
}

int RunFilter(const FilterArgs& args) {
  if (!IsExportExtension(args.output)) return Fail(InvalidArgument(args.output + ": output must end in .gltf, .glb or .bvh"), Stage::kOutput);
  if (IsSameFile(args.input, args.output) ||
      fs::path(args.input).lexically_normal() == fs::path(args.output).lexically_normal())
    return Fail(IoError(args.output + ": refusing to overwrite the input file"), Stage::kOutput);
  Result<Scene> scene = ImportFile(args.input, args.import);
  if (!scene.ok()) return Fail(scene.status(), Stage::kInput);
  for (const std::string& warning : scene->warnings) PrintWarning(args.input + ": " + warning);
  if (scene->clips.empty()) return Fail(InvalidData(args.input + ": no animation to filter"), Stage::kInput);

  MultiresFilterOptions options;
  options.gains.band_gains = args.gains;
  options.gains.residual_gain = args.residual_gain;
  options.pyramid.levels = args.levels;
  options.pyramid.boundary = args.periodic ? PyramidBoundary::kPeriodic : PyramidBoundary::kClamp;
  Result<std::vector<int>> joints = JointIndices(scene->skeleton, args.joints);
  if (!joints.ok()) return Fail(joints.status(), Stage::kInput);
  options.joints = *joints;
  TangentReference reference;
  if (!args.db.empty()) {
    Result<MotionDatabase> db = LoadDatabaseArg(args.db);
    if (!db.ok()) return Fail(db.status(), Stage::kInput);
    Result<TangentReference> mapped = ReferenceFor(scene->skeleton, *db);
    if (!mapped.ok()) return Fail(mapped.status().WithContext(args.input), Stage::kInput);
    reference = std::move(mapped).value();
    options.reference = &reference;
  }
  for (MotionClip& clip : scene->clips) {
    Result<MotionClip> filtered = MultiresFilter(scene->skeleton, clip, options);
    if (!filtered.ok()) return Fail(filtered.status().WithContext(args.input + ": clip '" + clip.name + "'"), Stage::kProcessing);
    if (!IsQuiet()) {
      const int levels = options.pyramid.levels > 0 ? options.pyramid.levels
                                                    : AutomaticLevels(clip.num_frames, clip.sample_rate_hz);
      std::string bands;
      char buffer[64];
      for (int k = 0; k < levels; ++k) {
        const double g = k < static_cast<int>(args.gains.size()) ? args.gains[k] : 1.0;
        std::snprintf(buffer, sizeof(buffer), " L%d %.2gHz x%g", k, BandPeakHz(k, clip.sample_rate_hz), g);
        bands += buffer;
      }
      std::printf("filtered '%s': %d frames, %d levels:%s, residual x%g\n", clip.name.c_str(), clip.num_frames,
                  levels, bands.c_str(), args.residual_gain);
    }
    clip = std::move(filtered).value();
  }
  const Status written = ExportFile(*scene, args.output, args.export_options);
  if (!written.ok()) return Fail(written, Stage::kOutput);
  return kExitOk;
}

}  // namespace

void AddFilterCommand(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<FilterArgs>();
  CLI::App* command = app.add_subcommand(
      "filter", "Multiresolution filtering: scale frequency bands of the motion (Bruderlin-Williams)");
  command->add_option("input", args->input, "Input motion file (.bvh .gltf .glb .fbx)")->required();
  command->add_option("-o,--output", args->output, "Output file (.glb .gltf .bvh)")->required();
  command->add_option("--gains", args->gains,
                      "Gains of the band-pass levels L0 (highest, ~15 Hz at 30 Hz), L1, ... comma-separated; "
                      "missing ones are 1")
      ->delimiter(',');
  command->add_option("--joints", args->joints, "Joints to filter, comma-separated (default: all; the motion root "
                                               "filters height, velocity and turning)")
      ->delimiter(',');
  command->add_option("--levels", args->levels, "Band-pass levels (default: floor(log2 frames), lowest band >= 0.1 Hz)")
      ->check(CLI::Range(0, 16));
  command->add_option("--residual-gain", args->residual_gain, "Gain of the residual low-pass (average pose and speed)");
  command->add_flag("--periodic", args->periodic, "Treat the clip as cyclic (wrap around instead of holding the ends)");
  command->add_option("--db", args->db, "Filter about this database's joint means (.mfdb file or motion folder)");
  AddImportFlags(*command, args->import);
  AddExportFlags(*command, args->export_options);
  command->footer(
      "Examples:\n"
      "  mocapfill filter walk.bvh -o lively.glb --gains 1,1,1.5,1.5,1,1\n"
      "  mocapfill filter walk.bvh -o arms.glb --gains 1,1,2 --joints UpperArm_L,LowerArm_L");
  command->callback([args, &action] { action = [args] { return RunFilter(*args); }; });
}

}  // namespace mocapfill::cli
