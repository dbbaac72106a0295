#include "converter/database_arg.h"

#include <memory>
#include <mutex>

#include "converter/console.h"
#include "formats/units_axes.h"

namespace mocapfill::cli {

void AddDatabaseBuildFlags(CLI::App& command, DatabaseBuildFlags& flags) {
  command.add_option("--rate", flags.rate_hz, "Working rate of the database in Hz (clips are resampled)")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command.add_option("--map", flags.map,
                     "Joint-name map, inline JSON or a JSON file {\"source name\": \"database name\"}, for clips whose "
                     "joints are named differently");
  command.add_option("--threads", flags.threads, "Import/build threads (0 = all cores)")->check(CLI::NonNegativeNumber);
  // --unit and --up as in AddImportFlags; its --rate (keyed-input sampling) is left to
  // detection here, because --rate names the database's working rate.
  command.add_option("--unit", flags.import.unit, "Length unit of the inputs: " + UnitChoicesText())
      ->check(CLI::IsMember(UnitChoices()))
      ->capture_default_str();
  command.add_option("--up", flags.import.up, "Up axis of the inputs: auto, y or z")
      ->check(CLI::IsMember({"auto", "y", "z"}))
      ->capture_default_str();
  AddMirrorFlag(command, flags.mirror);
}

void AddMirrorFlag(CLI::App& command, bool& mirror) {
  command
      .add_option_function<std::string>(
          "--mirror", [&mirror](const std::string& value) { mirror = value == "on"; },
          "on: add each clip's left/right mirror image to the database (named <clip>#mirror)")
      ->check(CLI::IsMember({"on", "off"}))
      ->default_str(mirror ? "on" : "off");
}

namespace {

// Draws the import progress of a database build on a terminal.
class ImportBar {
 public:
  ImportProgress callback() {
    return [this](size_t, size_t total) {
      std::call_once(started_, [&] { bar_ = std::make_unique<Progress>("importing", total); });
      bar_->Advance();
    };
  }

 private:
  std::once_flag started_;
  std::unique_ptr<Progress> bar_;
};

}  // namespace

Result<MotionDatabase> BuildDatabaseFromPaths(const std::vector<std::string>& paths, const DatabaseBuildFlags& flags) {
  ImportBar bar;
  return mocapfill::BuildDatabaseFromPaths(paths, flags, bar.callback());
}

Result<MotionDatabase> LoadDatabase(const std::vector<std::string>& paths, const DatabaseBuildFlags& flags) {
  ImportBar bar;
  return mocapfill::LoadDatabase(paths, flags, bar.callback());
}

Result<MotionDatabase> LoadDatabaseArg(const std::string& path, const DatabaseBuildFlags& flags) {
  return LoadDatabase({path}, flags);
}

}  // namespace mocapfill::cli
