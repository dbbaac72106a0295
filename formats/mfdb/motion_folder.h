// Reading a set of motion files for a database: folders are scanned recursively for every
// extension ImportFile reads, files are imported in parallel, and per-clip labels are taken
// from the file name and, for the Bandai-Namco set, the JSON beside each clip.
#pragma once

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "formats/motion_io.h"
#include "processing/core/scene.h"
#include "processing/core/status.h"

namespace mocapfill {

// Labels of one file:
//  - "file": the path; "name": the file stem.
//  - File names "<prefix>_<content>_<style>_<id>" with a numeric id (Bandai-Namco
//    "dataset-1_walk-back_old_001") give "content", "style", "id".
//  - A JSON object beside the file (same stem, ".json") contributes its scalar fields; the
//    Bandai-Namco {"content": 0, "style": 11} indices are resolved to names through
//    ../cfg/content_label.txt and style_label.txt (prefix "dataset-1_" stripped) when those
//    exist, else kept as numbers in "content_index"/"style_index". A malformed JSON is an
//    error naming it (kInvalidData); a missing one is not.
Result<std::map<std::string, std::string>> ReadClipLabels(const std::string& path);

struct LabeledScene {
  Scene scene;
  std::map<std::string, std::string> labels;
};

// Imports `files` on `threads` threads (0 = hardware concurrency), results in the order of
// `files`; `on_file_done` (may be empty) is called once per file from worker threads.
// The first failing file (in list order) fails the whole call, its path in the message.
Result<std::vector<LabeledScene>> ImportMotionFiles(const std::vector<std::string>& files,
                                                    const ImportOptions& options, int threads,
                                                    const std::function<void()>& on_file_done = {});

}  // namespace mocapfill
