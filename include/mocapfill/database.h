// A motion capture database: clips resampled to one rate on one rig, analysed for the fill
// methods. Opened from a built .mfdb file, or built in memory from motion files and
// folders, or the default database that ships with mocapfill.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "mocapfill/export.h"

namespace mocapfill::api {

struct DatabaseOptions {
  double rate_hz = 30.0;      // working rate when building (clips are resampled)
  std::string map;            // joint-name map, inline JSON {"source": "database joint"} or a JSON file
  int threads = 0;            // import and build threads (0 = every core)
  std::string unit = "auto";  // length unit of the motion files
  std::string up = "auto";    // up axis of the motion files
  bool mirror = false;        // add each clip's left/right mirror image ("<clip>#mirror")
};

// Called as files are imported: files done, files in all (from worker threads).
using ImportProgress = std::function<void(size_t done, size_t total)>;

class DatabaseAccess;

class MOCAPFILL_API Database {
 public:
  // `paths`: one .mfdb file, or motion files and folders to build from; empty or {"default"}
  // = the default database. Throws Error (kInvalidInput naming the file).
  static Database Open(const std::vector<std::string>& paths, const DatabaseOptions& options = {},
                       const ImportProgress& progress = {});
  static Database Open(const std::string& path, const DatabaseOptions& options = {},
                       const ImportProgress& progress = {});
  static Database Default(const ImportProgress& progress = {});

  // Writes the database as an .mfdb file. Throws Error (kOutput).
  void Save(const std::string& path) const;

  std::string name() const;  // what it was opened from ("default" for the default database)
  double rate_hz() const;
  int frame_count() const;
  int clip_count() const;
  std::vector<std::string> clip_names() const;
  std::vector<std::string> joint_names() const;

 private:
  friend class DatabaseAccess;
  struct Impl;
  explicit Database(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;  // immutable once built: copies share it
};

// Where the default database is read from: <prefix>/share/mocapfill/default_db beside the
// installed library, else the source tree's fixtures/default_db; "" when neither exists.
MOCAPFILL_API std::string DefaultDatabasePath();

}  // namespace mocapfill::api
