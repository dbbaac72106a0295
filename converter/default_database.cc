#include "converter/default_database.h"

#include <filesystem>

#include "converter/database_arg.h"

#ifndef MOCAPFILL_SOURCE_DEFAULT_DB
#define MOCAPFILL_SOURCE_DEFAULT_DB ""
#endif

namespace mocapfill::cli {

namespace fs = std::filesystem;

std::string DefaultDatabaseDir() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) {
    const fs::path installed = exe.parent_path().parent_path() / "share" / "mocapfill" / "default_db";
    if (fs::is_directory(installed, ec)) return installed.string();
  }
  const fs::path source(MOCAPFILL_SOURCE_DEFAULT_DB);
  if (!source.empty() && fs::is_directory(source, ec)) return source.string();
  return "";
}

Result<MotionDatabase> LoadDatabase(const std::vector<std::string>& paths) {
  if (paths.empty()) {
    const std::string dir = DefaultDatabaseDir();
    if (dir.empty()) return IoError("the default database is not installed; give --db FILE|FOLDER");
    return LoadDatabaseArg(dir);
  }
  if (paths.size() == 1) return LoadDatabaseArg(paths[0]);
  return BuildDatabaseFromPaths(paths, DatabaseBuildFlags{});
}

}  // namespace mocapfill::cli
