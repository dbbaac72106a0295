#include "converter/database_arg.h"

#include <filesystem>
#include <nlohmann/json.hpp>

#include "converter/console.h"
#include "formats/file_io.h"
#include "formats/mfdb/mfdb_file.h"
#include "formats/mfdb/motion_folder.h"
#include "processing/retargeting/retarget_scene.h"

#ifndef MOCAPFILL_SOURCE_DEFAULT_DB
#define MOCAPFILL_SOURCE_DEFAULT_DB ""
#endif

namespace mocapfill::cli {

void AddDatabaseBuildFlags(CLI::App& command, DatabaseBuildFlags& flags) {
  command.add_option("--rate", flags.rate_hz, "Working rate of the database in Hz (clips are resampled)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command.add_option("--map", flags.map_path,
                     "Joint-name map, JSON {\"source name\": \"database name\"}, for clips whose joints are named differently");
  command.add_option("--threads", flags.threads, "Import/build threads (0 = all cores)")->check(CLI::NonNegativeNumber);
  // --unit and --up as in AddImportFlags; its --rate (keyed-input sampling) is left to
  // detection here, because --rate names the database's working rate.
  command.add_option("--unit", flags.import.unit, "Length unit of the inputs: auto, m, cm, mm, in, ft, cmu")
      ->check(CLI::IsMember({"auto", "m", "cm", "mm", "in", "ft", "cmu"}))
      ->capture_default_str();
  command.add_option("--up", flags.import.up, "Up axis of the inputs: auto, y or z")
      ->check(CLI::IsMember({"auto", "y", "z"}))
      ->capture_default_str();
}

Result<std::map<std::string, std::string>> ParseJointNameMap(const std::string& text, const std::string& origin) {
  const nlohmann::json json = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (json.is_discarded() || !json.is_object())
    return InvalidData(origin + ": a joint-name map must be a JSON object {\"source name\": \"database name\"}");
  std::map<std::string, std::string> map;
  for (const auto& [key, value] : json.items()) {
    if (!value.is_string()) return InvalidData(origin + ": the value of \"" + key + "\" is not a string");
    map[key] = value.get<std::string>();
  }
  return map;
}

Result<std::map<std::string, std::string>> ReadJointNameMap(const std::string& path) {
  ASSIGN_OR_RETURN(const std::string text, ReadFileBytes(path));
  return ParseJointNameMap(text, path);
}

// Same joint names with the same parents, in any order (what the builder accepts as is).
bool SameJointSet(const Skeleton& a, const Skeleton& b) {
  if (a.num_joints() != b.num_joints()) return false;
  for (int j = 0; j < b.num_joints(); ++j) {
    const std::optional<int> in_a = a.Find(b.name(j));
    if (!in_a) return false;
    const int pa = a.parent(*in_a), pb = b.parent(j);
    if ((pa == kNoParent) != (pb == kNoParent) || (pa != kNoParent && a.name(pa) != b.name(pb))) return false;
  }
  return true;
}

Result<MotionDatabase> BuildDatabaseFromPaths(const std::vector<std::string>& paths, const DatabaseBuildFlags& flags) {
  ASSIGN_OR_RETURN(const std::vector<std::string> files, ListMotionFiles(paths));
  DatabaseOptions options;
  options.rate_hz = flags.rate_hz;
  options.threads = flags.threads;
  MotionDatabaseBuilder builder(options);
  if (!flags.map_path.empty()) {
    Result<std::map<std::string, std::string>> map = ReadJointNameMap(flags.map_path);
    if (!map.ok()) return map.status();
    builder.SetJointNameMap(std::move(map).value());
  }
  std::vector<LabeledScene> scenes;
  {
    Progress progress("importing", files.size());
    ASSIGN_OR_RETURN(scenes, ImportMotionFiles(files, flags.import, flags.threads, [&] { progress.Advance(); }));
  }
  // The database's rig as a retargeting target: its skeleton and first frame (for a rest pose
  // where the zero pose does not stand), kept before the builder takes the clips.
  Scene database_rig;
  if (!scenes.empty()) {
    database_rig.skeleton = scenes.front().scene.skeleton;
    if (!scenes.front().scene.clips.empty()) {
      MotionClip first = scenes.front().scene.clips.front();
      first.num_frames = 1;
      first.rotations.resize(first.num_joints);
      first.translations.resize(first.num_joints);
      database_rig.clips.push_back(std::move(first));
    }
  }
  for (LabeledScene& s : scenes) {
    const std::string& file = s.labels["file"];
    // A clip of another rig is retargeted onto the first file's rig (through the canonical
    // humanoid), unless a joint-name map was given to make the rigs match by name.
    if (flags.map_path.empty() && &s != &scenes.front() && !SameJointSet(scenes.front().scene.skeleton, s.scene.skeleton)) {
      Result<Scene> onto = RetargetScene(s.scene, database_rig);
      if (!onto.ok())
        return onto.status().WithContext(file + ": its rig differs from the database's (" + scenes.front().labels["file"] +
                                         ") and could not be retargeted onto it");
      s.scene.skeleton = onto->skeleton;
      s.scene.clips = std::move(onto->clips);
      s.labels["retargeted_from_rig"] = s.labels["file"];
    }
    for (MotionClip& clip : s.scene.clips) {
      // One clip per file is the rule (BVH); files with several animations name each.
      clip.name = s.scene.clips.size() == 1 ? s.labels["name"] : s.labels["name"] + ":" + clip.name;
      RETURN_IF_ERROR(builder.Add(s.scene.skeleton, std::move(clip), s.labels).WithContext(file));
    }
    s.scene.clips.clear();  // the builder holds the frames now
  }
  return builder.Build();
}

bool IsDatabaseFile(const std::string& path) { return LowerExtension(path) == ".mfdb" || LooksLikeMfdb(path); }

std::string DefaultDatabaseDir() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    // <prefix>/libexec/mocapfill/mocapfill-full, which runs the verbs that use it, or an
    // executable in <prefix>/bin.
    for (const fs::path& prefix : {exe.parent_path().parent_path().parent_path(), exe.parent_path().parent_path()}) {
      const fs::path installed = prefix / "share" / "mocapfill" / "default_db";
      if (fs::is_directory(installed, ec)) return installed.string();
    }
  }
  const fs::path source(MOCAPFILL_SOURCE_DEFAULT_DB);
  if (!source.empty() && fs::is_directory(source, ec)) return source.string();
  return "";
}

Result<MotionDatabase> LoadDatabase(const std::vector<std::string>& paths, const DatabaseBuildFlags& flags) {
  if (paths.empty()) {
    const std::string dir = DefaultDatabaseDir();
    if (dir.empty()) return IoError("the default database is not installed; give --db FILE|FOLDER");
    return BuildDatabaseFromPaths({dir}, flags);
  }
  if (paths.size() == 1 && IsDatabaseFile(paths[0])) return ReadMfdb(paths[0]);
  return BuildDatabaseFromPaths(paths, flags);
}

Result<MotionDatabase> LoadDatabaseArg(const std::string& path, const DatabaseBuildFlags& flags) {
  return LoadDatabase({path}, flags);
}

}  // namespace mocapfill::cli
