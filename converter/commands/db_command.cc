// mocapfill db build|info: index motion files into one .mfdb database file, and describe a
// database (a file, or a folder built in memory).
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <iostream>

#include "converter/commands.h"
#include "converter/console.h"
#include "converter/database_arg.h"
#include "converter/exit_codes.h"
#include "formats/file_io.h"
#include "formats/mfdb/mfdb_file.h"
#include "processing/filtering/pyramid.h"

namespace mocapfill::cli {

namespace {

using Clock = std::chrono::steady_clock;

double MillisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

struct DbBuildArgs {
  std::vector<std::string> inputs;
  std::string output;
  DatabaseBuildFlags build;
};

struct DbInfoArgs {
  std::string database;
  bool json = false;
  bool clips = false;
  DatabaseBuildFlags build;
};

std::string BandList(const MotionDatabase& db) {
  std::string text;
  char buffer[64];
  for (const StoredBand& b : db.bands()) {
    std::snprintf(buffer, sizeof(buffer), "%sL%d (%.2f Hz)", text.empty() ? "" : " ", b.band, b.peak_hz);
    text += buffer;
  }
  return text;
}

// label key -> value -> number of clips, e.g. content -> walk -> 60.
std::map<std::string, std::map<std::string, int>> LabelCounts(const MotionDatabase& db) {
  std::map<std::string, std::map<std::string, int>> counts;
  for (const ClipRange& c : db.clips())
    for (const char* key : {"content", "style"})
      if (auto it = c.labels.find(key); it != c.labels.end()) ++counts[key][it->second];
  return counts;
}

int RunBuild(const DbBuildArgs& args) {
  if (LowerExtension(args.output) != ".mfdb") {
    PrintError(args.output + ": the database file must end in .mfdb");
    return kExitUsage;
  }
  const Clock::time_point start = Clock::now();
  Result<MotionDatabase> db = BuildDatabaseFromPaths(args.inputs, args.build);
  if (!db.ok()) {
    PrintError(db.status().message());
    return ExitCodeFor(db.status(), Stage::kInput);
  }
  const double build_ms = MillisecondsSince(start);
  const std::string bytes = SerializeMfdb(*db);
  const Status written = WriteFileAtomic(args.output, bytes);
  if (!written.ok()) {
    PrintError(written.message());
    return ExitCodeFor(written, Stage::kOutput);
  }
  if (!IsQuiet())
    std::printf("built %s: %d clips, %d frames at %g Hz, %d joints, %d channels, bands %s; %.1f MB in %.0f ms "
                "(+%.0f ms to write)\n",
                args.output.c_str(), db->num_clips(), db->num_frames(), db->rate_hz(), db->num_joints(),
                db->num_channels(), BandList(*db).c_str(), bytes.size() / 1e6, build_ms,
                MillisecondsSince(start) - build_ms);
  return kExitOk;
}

// Wall and CPU time of the load; CPU time stays meaningful when other jobs share the machine.
struct LoadTime {
  double wall_ms = 0.0;
  double cpu_ms = 0.0;
};

nlohmann::ordered_json DescribeJson(const MotionDatabase& db, const DbInfoArgs& args, const LoadTime& load) {
  nlohmann::ordered_json out;
  out["database"] = args.database;
  out["kind"] = IsDatabaseFile(args.database) ? "mfdb" : "built in memory";
  out["load_ms"] = load.wall_ms;
  out["load_cpu_ms"] = load.cpu_ms;
  out["memory_bytes"] = db.MemoryBytes();
  out["rate_hz"] = db.rate_hz();
  out["joints"] = db.num_joints();
  out["root_joint"] = db.root_joint() >= 0 ? nlohmann::ordered_json(db.skeleton().name(db.root_joint())) : nullptr;
  out["clips"] = db.num_clips();
  out["frames"] = db.num_frames();
  out["duration_s"] = db.num_frames() / db.rate_hz();
  out["channels"] = db.num_channels();
  nlohmann::ordered_json bands = nlohmann::ordered_json::array();
  for (const StoredBand& b : db.bands()) bands.push_back({{"band", b.band}, {"peak_hz", b.peak_hz}});
  out["bands"] = bands;
  const CorrelationTable& corr = db.correlation();
  out["correlation"] = {{"band", corr.band},
                        {"peak_hz", corr.band >= 0 ? BandPeakHz(corr.band, db.rate_hz()) : 0.0},
                        {"max_lag_frames", corr.max_lag_frames},
                        {"channels", corr.num_channels}};
  out["labels"] = LabelCounts(db);
  if (args.clips) {
    nlohmann::ordered_json clips = nlohmann::ordered_json::array();
    for (const ClipRange& c : db.clips())
      clips.push_back({{"name", c.name}, {"first_frame", c.first_frame}, {"frames", c.num_frames}, {"labels", c.labels}});
    out["clip_list"] = clips;
  }
  return out;
}

void PrintText(const MotionDatabase& db, const DbInfoArgs& args, const LoadTime& load) {
  std::printf("database:    %s (%s), loaded in %.1f ms (%.1f ms CPU), %.1f MB of signals\n", args.database.c_str(),
              IsDatabaseFile(args.database) ? "mfdb file" : "built in memory", load.wall_ms, load.cpu_ms,
              db.MemoryBytes() / 1e6);
  std::printf("skeleton:    %d joints, motion root %s\n", db.num_joints(),
              db.root_joint() >= 0 ? ("'" + db.skeleton().name(db.root_joint()) + "'").c_str() : "(none)");
  std::printf("frames:      %d at %g Hz (%.1f s) in %d clips\n", db.num_frames(), db.rate_hz(),
              db.num_frames() / db.rate_hz(), db.num_clips());
  std::printf("channels:    %d (%d tangent + %d root features)\n", db.num_channels(), 3 * db.num_joints(),
              db.num_channels() - 3 * db.num_joints());
  std::printf("bands:       %s\n", BandList(db).c_str());
  const CorrelationTable& corr = db.correlation();
  std::printf("correlation: band L%d, lags up to %d frames (%.2f s)\n", corr.band, corr.max_lag_frames,
              corr.max_lag_frames / db.rate_hz());
  for (const auto& [key, values] : LabelCounts(db)) {
    std::string line;
    for (const auto& [value, n] : values) line += (line.empty() ? "" : ", ") + value + " " + std::to_string(n);
    std::printf("%-12s %s\n", (key + ":").c_str(), line.c_str());
  }
  if (args.clips)
    for (const ClipRange& c : db.clips()) std::printf("  %-48s %6d frames\n", c.name.c_str(), c.num_frames);
}

int RunInfo(const DbInfoArgs& args) {
  const Clock::time_point start = Clock::now();
  const std::clock_t cpu_start = std::clock();
  Result<MotionDatabase> db = LoadDatabaseArg(args.database, args.build);
  const LoadTime load{MillisecondsSince(start), 1000.0 * (std::clock() - cpu_start) / CLOCKS_PER_SEC};
  if (!db.ok()) {
    PrintError(db.status().message());
    return ExitCodeFor(db.status(), Stage::kInput);
  }
  if (args.json) {
    std::cout << DescribeJson(*db, args, load).dump(2) << "\n";
  } else {
    PrintText(*db, args, load);
  }
  return kExitOk;
}

}  // namespace

void AddDbCommand(CLI::App& app, CommandAction& action) {
  CLI::App* db = app.add_subcommand("db", "Build or describe a motion database (.mfdb)");
  db->require_subcommand(1);

  auto build = std::make_shared<DbBuildArgs>();
  CLI::App* b = db->add_subcommand("build", "Index BVH/glTF/FBX files under folders into one .mfdb file");
  b->add_option("inputs", build->inputs, "Motion files or folders (searched recursively)")->required();
  b->add_option("-o,--output", build->output, "Database file to write (.mfdb)")->required();
  AddDatabaseBuildFlags(*b, build->build);
  b->footer("Examples:\n  mocapfill db build ../shared/data/bandai-namco-1/data -o bn1.mfdb\n"
            "  mocapfill db build takes/ more.fbx -o mix.mfdb --map names.json --rate 30\n"
            "  mocapfill db build ../shared/data/bandai-namco-1/data -o bn1m.mfdb --mirror on");
  b->callback([build, &action] { action = [build] { return RunBuild(*build); }; });

  auto info = std::make_shared<DbInfoArgs>();
  CLI::App* i = db->add_subcommand("info", "Describe a database: clips, frames, labels, bands, load time");
  i->add_option("database", info->database, "An .mfdb file, or a folder of motion files (built in memory)")->required();
  i->add_flag("--json", info->json, "Print JSON (includes load_ms)");
  i->add_flag("--clips", info->clips, "List every clip");
  AddDatabaseBuildFlags(*i, info->build);
  i->footer("Examples:\n  mocapfill db info bn1.mfdb\n  mocapfill db info bn1.mfdb --json | jq .load_ms");
  i->callback([info, &action] { action = [info] { return RunInfo(*info); }; });
}

}  // namespace mocapfill::cli
