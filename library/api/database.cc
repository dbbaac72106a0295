#include "formats/mfdb/mfdb_file.h"
#include "library/api/access.h"
#include "library/database_loading.h"

namespace mocapfill::api {

Database DatabaseAccess::Wrap(MotionDatabase database, std::string name) {
  auto impl = std::make_shared<Database::Impl>();
  impl->database = std::move(database);
  impl->name = std::move(name);
  return Database(std::move(impl));
}

Database::Database(std::shared_ptr<const Impl> impl) : impl_(std::move(impl)) {}

Database Database::Open(const std::vector<std::string>& paths, const DatabaseOptions& options,
                        const ImportProgress& progress) {
  DatabaseBuildOptions build;
  build.rate_hz = options.rate_hz;
  build.map = options.map;
  build.threads = options.threads;
  build.import.unit = options.unit;
  build.import.up = options.up;
  build.mirror = options.mirror;
  if (!(options.rate_hz > 0.0))
    ThrowIfError(InvalidArgument("rate_hz: must be positive"), FailureStage::kInput);
  Result<MotionDatabase> database = LoadDatabase(paths, build, progress);
  const bool is_default = paths.empty() || (paths.size() == 1 && paths[0] == "default");
  std::string name = is_default ? "default" : paths[0];
  if (paths.size() > 1) name += " (+" + std::to_string(paths.size() - 1) + ")";
  return DatabaseAccess::Wrap(ValueOrThrow(std::move(database), FailureStage::kInput), std::move(name));
}

Database Database::Open(const std::string& path, const DatabaseOptions& options, const ImportProgress& progress) {
  return Open(std::vector<std::string>{path}, options, progress);
}

Database Database::Default(const ImportProgress& progress) { return Open(std::vector<std::string>{}, {}, progress); }

void Database::Save(const std::string& path) const {
  ThrowIfError(WriteMfdb(impl_->database, path), FailureStage::kOutput);
}

std::string DefaultDatabasePath() { return DefaultDatabaseDir(); }

std::string Database::name() const { return impl_->name; }
double Database::rate_hz() const { return impl_->database.rate_hz(); }
int Database::frame_count() const { return impl_->database.num_frames(); }
int Database::clip_count() const { return impl_->database.num_clips(); }

std::vector<std::string> Database::clip_names() const {
  std::vector<std::string> names;
  for (const ClipRange& clip : impl_->database.clips()) names.push_back(clip.name);
  return names;
}

std::vector<std::string> Database::joint_names() const {
  std::vector<std::string> names;
  for (const Joint& joint : impl_->database.skeleton().joints()) names.push_back(joint.name);
  return names;
}

}  // namespace mocapfill::api
