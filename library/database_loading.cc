#include "library/database_loading.h"

#include <dlfcn.h>

#include <atomic>
#include <filesystem>
#include <optional>

#include "formats/file_io.h"
#include "formats/mfdb/mfdb_file.h"
#include "formats/mfdb/motion_folder.h"
#include "formats/name_map_json.h"
#include "processing/database/motion_database_builder.h"
#include "processing/retargeting/retarget_scene.h"

#ifndef MOCAPFILL_SOURCE_DEFAULT_DB
#define MOCAPFILL_SOURCE_DEFAULT_DB ""
#endif

namespace mocapfill {

namespace {

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

// The database's rig as a retargeting target: the first scene's skeleton and first frame
// (for a rest pose where the zero pose does not stand), kept before the builder takes the clips.
Scene DatabaseRig(const Scene& first) {
  Scene rig;
  rig.skeleton = first.skeleton;
  if (!first.clips.empty()) {
    MotionClip frame = first.clips.front();
    frame.num_frames = 1;
    frame.rotations.resize(frame.num_joints);
    frame.translations.resize(frame.num_joints);
    rig.clips.push_back(std::move(frame));
  }
  return rig;
}

// The files whose folder may hold the installation: the executable, and the shared library
// this code is linked into (the public API's, which a Python module or another program loads).
std::vector<std::filesystem::path> InstalledBinaries() {
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) files.push_back(exe);
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&DefaultDatabaseDir), &info) != 0 && info.dli_fname != nullptr) {
    // Canonical: a library found through $ORIGIN/../.. is named by that unresolved path.
    const fs::path library = fs::weakly_canonical(fs::absolute(info.dli_fname, ec), ec);
    if (!ec && library != exe) files.push_back(library);
  }
  return files;
}

}  // namespace

Result<MotionDatabase> BuildDatabaseFromPaths(const std::vector<std::string>& paths, const DatabaseBuildOptions& options,
                                              const ImportProgress& progress) {
  ASSIGN_OR_RETURN(const std::vector<std::string> files, ListMotionFiles(paths));
  DatabaseOptions database_options;
  database_options.rate_hz = options.rate_hz;
  database_options.threads = options.threads;
  database_options.mirror = options.mirror;
  MotionDatabaseBuilder builder(database_options);
  if (!options.map.empty()) {
    Result<std::map<std::string, std::string>> map = ReadNameMap(options.map, "--map", kJointNameMapShape);
    if (!map.ok()) return map.status();
    builder.SetJointNameMap(std::move(map).value());
  }
  std::atomic<size_t> done{0};
  const auto on_file = [&] {
    const size_t n = ++done;
    if (progress) progress(n, files.size());
  };
  ASSIGN_OR_RETURN(std::vector<LabeledScene> scenes, ImportMotionFiles(files, options.import, options.threads, on_file));
  const Scene database_rig = scenes.empty() ? Scene{} : DatabaseRig(scenes.front().scene);
  for (LabeledScene& s : scenes) {
    const std::string& file = s.labels["file"];
    // A clip of another rig is retargeted onto the first file's rig (through the canonical
    // humanoid), unless a joint-name map was given to make the rigs match by name.
    if (options.map.empty() && &s != &scenes.front() &&
        !SameJointSet(scenes.front().scene.skeleton, s.scene.skeleton)) {
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
  for (const fs::path& binary : InstalledBinaries()) {
    // <prefix>/bin/mocapfill, <prefix>/lib/libmocapfill.so, or
    // <prefix>/libexec/mocapfill/mocapfill-full (which runs the verbs that use it).
    for (const fs::path& prefix : {binary.parent_path().parent_path(), binary.parent_path().parent_path().parent_path()}) {
      const fs::path installed = prefix / "share" / "mocapfill" / "default_db";
      if (fs::is_directory(installed, ec)) return installed.string();
    }
  }
  const fs::path source(MOCAPFILL_SOURCE_DEFAULT_DB);
  if (!source.empty() && fs::is_directory(source, ec)) return source.string();
  return "";
}

Result<MotionDatabase> LoadDatabase(const std::vector<std::string>& paths, const DatabaseBuildOptions& options,
                                    const ImportProgress& progress) {
  if (paths.empty() || (paths.size() == 1 && paths[0] == "default")) {
    const std::string dir = DefaultDatabaseDir();
    if (dir.empty()) return IoError("the default database is not installed; give a .mfdb file or motion files/folders");
    return BuildDatabaseFromPaths({dir}, options, progress);
  }
  if (paths.size() == 1 && IsDatabaseFile(paths[0])) return ReadMfdb(paths[0]);
  return BuildDatabaseFromPaths(paths, options, progress);
}

}  // namespace mocapfill
