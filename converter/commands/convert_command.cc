// mocapfill convert: any importable file to .gltf, .glb or .bvh; many files at once in
// one process, spread over all cores.
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/exit_codes.h"
#include "converter/export_flags.h"
#include "converter/import_flags.h"
#include "converter/std_streams.h"
#include "formats/atomic_writer.h"
#include "formats/file_io.h"
#include "formats/motion_io.h"
#include "processing/retargeting/retarget_scene.h"
#include "formats/units_axes.h"

namespace mocapfill::cli {

namespace {

namespace fs = std::filesystem;

struct ConvertArgs {
  std::vector<std::string> inputs;
  std::string output;      // second positional: an output file (single input)
  std::string output_dir;  // -o: a folder for one or many inputs
  std::string format = "glb";
  int jobs = 0;
  ImportOptions import;
  ExportOptions export_options;
  std::string retarget;       // --retarget: a character whose rig the motion is put onto
  std::string retarget_rest = "auto";
  std::string from;           // format of a "-" input (standard input)
  bool json = false;          // a JSON summary on standard output
};

// The character of --retarget, read once for every input.
struct RetargetTarget {
  Scene character;
  RigOptions rig;
};

struct Job {
  std::string input;
  std::string output;
};

// What became of one job: its exit code, error and import warnings, for the terminal and --json.
struct JobResult {
  int code = kExitOk;
  std::string error;
  std::vector<std::string> warnings;
};

JobResult Failed(const Status& status, Stage stage) { return {ExitCodeFor(status, stage), status.message(), {}}; }

// Every input by file identity, built once: checking each output against each input
// pairwise would cost two stat calls per pair, 60,000 for a batch of 174. An input that cannot
// be identified (stat fails) is kept by normalised path instead; one that can is the same file
// as any path naming it, which its identity already says, so the batch does not normalise
// paths, which would delay the start of every worker.
struct InputSet {
  std::set<FileId> ids;
  std::set<std::string> unidentified_paths;

  explicit InputSet(const std::vector<std::string>& inputs) {
    for (const std::string& in : inputs) {
      if (const std::optional<FileId> id = IdentifyFile(in))
        ids.insert(*id);
      else
        unidentified_paths.insert(fs::path(in).lexically_normal().string());
    }
  }
  bool Contains(const std::string& path) const {
    if (const std::optional<FileId> id = IdentifyFile(path); id && ids.count(*id) > 0) return true;
    return !unidentified_paths.empty() && unidentified_paths.count(fs::path(path).lexically_normal().string()) > 0;
  }
};

// Imports, puts the motion onto the character's rig, exports.
JobResult RetargetOne(const Job& job, const ConvertArgs& args, const ImportOptions& import, const RetargetTarget& target,
                      AtomicWriter* writer) {
  Result<Scene> motion = ImportFile(job.input, import);
  if (!motion.ok()) return Failed(motion.status(), Stage::kInput);
  JobResult result;
  for (const std::string& warning : motion->warnings) result.warnings.push_back(job.input + ": " + warning);
  Result<Scene> retargeted = RetargetScene(*motion, target.character, {}, target.rig);
  if (!retargeted.ok()) {
    const Status status = retargeted.status().WithContext(job.input + " onto " + args.retarget);
    return {ExitCodeFor(status, Stage::kInput), status.message(), result.warnings};
  }
  retargeted->source = motion->source;  // units and frame timing as the motion had them
  const Status written = ExportFile(*retargeted, job.output, args.export_options, writer);
  if (!written.ok()) return {ExitCodeFor(written, Stage::kOutput), written.message(), result.warnings};
  return result;
}

// Converts one file (or retargets it when a target is given).
JobResult ConvertOne(const Job& job, const ConvertArgs& args, const ImportOptions& import,
                     const ConvertOptions& convert, const InputSet& all_inputs, const RetargetTarget* target,
                     AtomicWriter* writer) {
  if (all_inputs.Contains(job.output)) return {kExitOutput, job.output + ": refusing to overwrite input file", {}};
  if (target) return RetargetOne(job, args, import, *target, writer);
  const ConvertResult converted = ConvertFile(job.input, job.output, import, args.export_options, convert, writer);
  JobResult result;
  for (const std::string& warning : converted.warnings) result.warnings.push_back(job.input + ": " + warning);
  if (!converted.status.ok()) {
    result.code = ExitCodeFor(converted.status, converted.failed_writing ? Stage::kOutput : Stage::kInput);
    result.error = converted.status.message();
  }
  return result;
}

// The output files of a folder input: its motion files, recursively, at the same relative
// paths under the output folder.
Status PlanFolder(const std::string& folder, const ConvertArgs& args, std::vector<Job>& jobs) {
  ASSIGN_OR_RETURN(const std::vector<std::string> files, ListMotionFiles({folder}));
  for (const std::string& file : files) {
    fs::path out = fs::path(args.output_dir) / fs::path(file).lexically_relative(folder);
    out.replace_extension("." + args.format);
    std::error_code ec;
    fs::create_directories(out.parent_path(), ec);
    if (ec) return IoError(out.parent_path().string() + ": cannot create output folder (" + ec.message() + ")");
    jobs.push_back({file, out.string()});
  }
  return OkStatus();
}

Result<std::vector<Job>> PlanJobs(const ConvertArgs& args) {
  std::vector<Job> jobs;
  if (!args.output.empty()) {
    if (!args.output_dir.empty()) return InvalidArgument("give either an output file or -o DIR, not both");
    if (args.inputs.size() != 1)
      return InvalidArgument("several inputs need an output folder: mocapfill convert IN... -o DIR");
    std::error_code ec;
    if (fs::is_directory(args.inputs[0], ec))
      return InvalidArgument(args.inputs[0] + ": a folder converts into a folder: mocapfill convert FOLDER -o DIR");
    if (!IsExportExtension(args.output))
      return InvalidArgument(args.output + ": output must end in .gltf, .glb or .bvh");
    jobs.push_back({args.inputs[0], args.output});
    return jobs;
  }
  if (args.output_dir.empty()) return InvalidArgument("missing output: mocapfill convert IN OUT, or IN... -o DIR");
  std::error_code ec;
  fs::create_directories(args.output_dir, ec);
  if (!fs::is_directory(args.output_dir))
    return IoError(args.output_dir + ": cannot create output folder");
  for (const std::string& in : args.inputs) {
    if (fs::is_directory(in, ec))
      RETURN_IF_ERROR(PlanFolder(in, args, jobs));
    else
      jobs.push_back({in, (fs::path(args.output_dir) / fs::path(in).stem()).string() + "." + args.format});
  }
  // Two inputs with the same stem would write the same output: refuse before any work.
  std::vector<std::string> outs;
  for (const Job& job : jobs) outs.push_back(job.output);
  std::sort(outs.begin(), outs.end());
  const auto dup = std::adjacent_find(outs.begin(), outs.end());
  if (dup != outs.end()) return InvalidArgument(*dup + ": two inputs would write this same output file");
  return jobs;
}

// --json: every job with its outcome, and the totals.
void PrintJson(const std::vector<Job>& jobs, const std::vector<JobResult>& results, const std::string& stdin_path) {
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  size_t failed = 0;
  for (size_t i = 0; i < jobs.size(); ++i) {
    const JobResult& r = results[i];
    failed += r.code != kExitOk;
    nlohmann::ordered_json warnings = nlohmann::ordered_json::array();
    for (const std::string& w : r.warnings) warnings.push_back(AsGiven(w, stdin_path));
    files.push_back({{"input", AsGiven(jobs[i].input, stdin_path)},
                     {"output", jobs[i].output},
                     {"ok", r.code == kExitOk},
                     {"exit_code", r.code},
                     {"error", r.code == kExitOk ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(AsGiven(r.error, stdin_path))},
                     {"warnings", warnings}});
  }
  const nlohmann::ordered_json out = {{"converted", jobs.size() - failed}, {"failed", failed}, {"files", files}};
  std::printf("%s\n", out.dump(2).c_str());
}

int RunConvert(ConvertArgs args) {
  // "-": standard input spooled to a file, standard output written through one.
  std::optional<TemporaryFile> stdin_file, stdout_file;
  if (std::count(args.inputs.begin(), args.inputs.end(), "-") > 0) {
    if (args.inputs.size() != 1) {
      PrintError("-: standard input can only be the one input");
      return kExitUsage;
    }
    Result<TemporaryFile> spooled = SpoolStdin(args.from);
    if (!spooled.ok()) return Fail(spooled.status(), Stage::kInput);
    stdin_file.emplace(std::move(spooled).value());
    args.inputs[0] = stdin_file->path();
  }
  if (IsStdStream(args.output)) {
    if (args.json) {
      PrintError("--json and an output on standard output (-) cannot share it");
      return kExitUsage;
    }
    Result<TemporaryFile> temporary = TemporaryFile::Create(args.format);
    if (!temporary.ok()) return Fail(temporary.status(), Stage::kOutput);
    stdout_file.emplace(std::move(temporary).value());
    args.output = stdout_file->path();
  }
  const std::string stdin_path = stdin_file ? stdin_file->path() : "";
  Result<std::vector<Job>> planned = PlanJobs(args);
  if (!planned.ok()) {
    PrintError(AsGiven(planned.status().message(), stdin_path));
    return ExitCodeFor(planned.status(), Stage::kOutput);
  }
  const std::vector<Job>& jobs = *planned;
  std::vector<JobResult> results(jobs.size());
  const bool one_job = jobs.size() == 1;
  size_t workers = 1;
  if (!one_job) {  // one job needs no count of the CPUs, which is a file to open and read
    const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
    workers = std::min<size_t>(jobs.size(), args.jobs > 0 ? args.jobs : hardware);
  }
  // Files spread over the workers already keep the cores busy: each is read on one thread.
  const ImportOptions& import = args.import;
  ConvertOptions convert;
  if (workers > 1) convert.threads = 1;
  // One file: the process ends right after it, and its exit unmaps the input faster (so
  // smaller inputs are mapped too, formats/file_io.h).
  convert.leave_input_to_exit = one_job && !stdin_file;
  // Many files one after another: freed buffers stay with the process for the next file
  // instead of going back to the kernel and being faulted in afresh.
  if (!one_job) PrepareBatchConversion();
  std::optional<RetargetTarget> target;
  std::vector<std::string> read_files;
  for (const Job& job : jobs) read_files.push_back(job.input);
  if (!args.retarget.empty()) {
    Result<Scene> character = ImportFile(args.retarget, args.import);
    if (!character.ok()) return Fail(character.status(), Stage::kInput);
    Result<RestSource> rest = ParseRestSource(args.retarget_rest);
    if (!rest.ok()) return Fail(rest.status(), Stage::kInput);
    target = RetargetTarget{std::move(*character), RigOptions{{}, *rest}};
    read_files.push_back(args.retarget);
  }
  // A batch killed with SIGKILL leaves its temporary files; the next batch into the folder
  // removes them (a single conversion does not read the folder: start-up is most of its time).
  if (!args.output_dir.empty()) RemoveStaleTemporaries(args.output_dir);
  Progress progress("converting", jobs.size());
  const InputSet inputs(read_files);
  std::atomic<size_t> next{0};
  auto work = [&] {
    // This worker's: re-used replaced outputs (formats/atomic_writer.h). A kept file only
    // pays off for a next output; one job removes the file it replaced at once, with no
    // signal handlers installed to clean up after it.
    AtomicWriter writer;
    AtomicWriter* const reuse = one_job ? nullptr : &writer;
    for (size_t i = next++; i < jobs.size(); i = next++) {
      results[i] = ConvertOne(jobs[i], args, import, convert, inputs, target ? &*target : nullptr, reuse);
      for (const std::string& warning : results[i].warnings) PrintWarning(AsGiven(warning, stdin_path));
      if (results[i].code != kExitOk) PrintError(AsGiven(results[i].error, stdin_path));
      progress.Advance();
    }
  };
  // This thread is one of the workers.
  {
    std::vector<std::jthread> helpers;
    for (size_t t = 1; t < workers; ++t) {
      try {
        helpers.emplace_back(work);
      } catch (const std::system_error&) {
        break;  // fewer threads than asked for: the ones there are take all the files
      }
    }
    work();
  }  // joined
  if (args.json) PrintJson(jobs, results, stdin_path);
  // Every input was tried; each failure has been reported with its file. A batch ends with a
  // count, so a long log still says how much is missing.
  const size_t failed =
      static_cast<size_t>(std::count_if(results.begin(), results.end(), [](const JobResult& r) { return r.code != kExitOk; }));
  if (failed > 0 && !one_job)
    PrintError(std::to_string(failed) + " of " + std::to_string(jobs.size()) + " inputs failed; " +
               std::to_string(jobs.size() - failed) + " converted");
  for (const JobResult& r : results)
    if (r.code != kExitOk) return r.code;  // the first failure in input order decides
  if (stdout_file) {
    const Status copied = CopyToStdout(stdout_file->path());
    if (!copied.ok()) return Fail(copied, Stage::kOutput);
  }
  return kExitOk;
}

}  // namespace

void AddConvertCommand(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<ConvertArgs>();
  CLI::App* command = app.add_subcommand("convert", "Convert BVH, glTF, GLB or FBX files to .glb, .gltf or .bvh");
  command->add_option("inputs", args->inputs,
                      "Input files or folders (.bvh .gltf .glb .fbx; - for standard input), then optionally one output "
                      "file (- for standard output, in --format)")
      ->required();
  command->add_option("-o,--output-dir", args->output_dir, "Output folder for one or many inputs");
  command->add_option("--format", args->format, "Output format with -o or for - (standard output): glb, gltf or bvh")
      ->check(CLI::IsMember({"glb", "gltf", "bvh"}))
      ->capture_default_str();
  command->add_option("-j,--jobs", args->jobs, "Parallel conversions (default: all cores)")->check(CLI::NonNegativeNumber);
  command->add_option("--out-unit", args->export_options.unit,
                      "BVH output unit: " + UnitChoicesText() + " (auto: the source's unit)")
      ->check(CLI::IsMember(UnitChoices()))
      ->capture_default_str();
  command->add_option("--retarget", args->retarget,
                      "Put the motion onto this character's rig (.bvh .gltf .glb .fbx); the output is the character "
                      "(its meshes and skins) with the motion");
  command->add_option("--retarget-rest", args->retarget_rest,
                      "The character's rest pose: auto (bind pose of a skin, else zero pose, else mean pose of its "
                      "clip, else first frame), bind, zero, mean or first-frame")
      ->check(CLI::IsMember(RestSourceNames()))
      ->capture_default_str();
  command->add_option("--from", args->from, "Format of a - input (standard input): bvh, gltf, glb or fbx")
      ->check(CLI::IsMember({"bvh", "gltf", "glb", "fbx"}));
  command->add_flag("--json", args->json, "Print a JSON summary (every file, its output, error and warnings) on stdout");
  AddImportFlags(*command, args->import);
  AddExportFlags(*command, args->export_options);
  command->footer(
      "Examples:\n"
      "  mocapfill convert walk.bvh walk.glb\n"
      "  mocapfill convert mocap/ -o out/ --json           # a folder, recursively, into a folder\n"
      "  cat walk.bvh | mocapfill convert - - --from bvh --format glb > walk.glb\n"
      "  mocapfill convert walk.bvh geno_walk.glb --retarget Geno.fbx   # onto another character\n"
      "  mocapfill convert clips/*.bvh -o out/            # batch, all cores\n"
      "  mocapfill convert mocap.bvh mocap.glb --unit cmu  # CMU units\n"
      "  mocapfill convert rig.fbx rig.gltf --animation Take1\n"
      "  mocapfill convert walk.glb walk.bvh\n"
      "  mocapfill convert walk.bvh walk.glb --skeleton-mesh   # shows as an armature in Blender\n"
      "  mocapfill convert walk.glb walk.bvh --bvh-layout standard   # for three.js and other readers");
  command->callback([args, &action] {
    // Without -o, the last positional is the output file: convert IN OUT.
    if (args->output_dir.empty() && args->inputs.size() >= 2) {
      args->output = args->inputs.back();
      args->inputs.pop_back();
    }
    action = [args] { return RunConvert(*args); };  // a copy: "-" arguments are replaced by files
  });
}

}  // namespace mocapfill::cli
