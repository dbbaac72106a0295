#include "converter/import_flags.h"

#include "formats/units_axes.h"

namespace mocapfill::cli {

void AddImportFlags(CLI::App& command, ImportOptions& options) {
  command.add_option("--unit", options.unit,
                     "Length unit of the input: " + UnitChoicesText() +
                         " (BVH default: cm, or detected from skeleton height when implausible)")
      ->check(CLI::IsMember(UnitChoices()))
      ->capture_default_str();
  command.add_option("--up", options.up, "Up axis of the input: auto, y or z (z-up is rotated to glTF's y-up)")
      ->check(CLI::IsMember({"auto", "y", "z"}))
      ->capture_default_str();
  command.add_option("--rate", options.rate_hz,
                     "Sampling rate (Hz) for keyed inputs (glTF, FBX); 0 detects it from the key times")
      ->check(CLI::Range(0.0, 1000.0))
      ->capture_default_str();
  command.add_option("--animation", options.animation, "glTF/FBX: animation to read, by name or index (default: all)");
  command.add_flag("--strict", options.strict, "Treat import warnings (e.g. BVH frame-count mismatch) as errors");
}

}  // namespace mocapfill::cli
