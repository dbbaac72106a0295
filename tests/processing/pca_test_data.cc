#include "tests/processing/pca_test_data.h"

#include <gtest/gtest.h>

#include "formats/mfdb/motion_folder.h"
#include "formats/motion_io.h"
#include "processing/database/motion_database_builder.h"
#include "tests/support/test_paths.h"

namespace mocapfill::testing {

namespace {

// The fifteen styles of dataset-1 (cfg/style_label.txt).
const char* const kStyles[] = {"active", "angry", "childish", "chimpira", "feminine", "giant",  "happy", "masculinity",
                               "musical", "normal", "not-confident", "old", "proud", "sad", "tired"};

}  // namespace

std::string BandaiClipPath(const std::string& content, const std::string& style, int id) {
  char name[128];
  std::snprintf(name, sizeof(name), "bandai-namco-1/data/dataset-1_%s_%s_%03d.bvh", content.c_str(), style.c_str(), id);
  return DataPath(name);
}

std::vector<std::string> BandaiPathsExcept(const std::string& content, const std::string& held_out_style) {
  std::vector<std::string> paths;
  for (const char* style : kStyles)
    if (held_out_style != style)
      for (int id = 1; id <= 2; ++id) {
        const std::string path = BandaiClipPath(content, style, id);
        if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
          std::fclose(f);
          paths.push_back(path);
        }
      }
  return paths;
}

Result<MotionDatabase> BuildBandaiDatabase(const std::vector<std::string>& paths) {
  ASSIGN_OR_RETURN(std::vector<LabeledScene> scenes, ImportMotionFiles(paths, ImportOptions{}, 0));
  MotionDatabaseBuilder builder;
  for (LabeledScene& s : scenes)
    for (MotionClip& clip : s.scene.clips) RETURN_IF_ERROR(builder.Add(s.scene.skeleton, std::move(clip), s.labels));
  return builder.Build();
}

Result<Scene> ImportBandaiClip(const std::string& path) { return ImportFile(path, ImportOptions{}); }

std::vector<std::string> BandaiLegJoints() {
  return {"Hips",  "UpperLeg_L", "LowerLeg_L", "Foot_L", "Toes_L",
          "UpperLeg_R", "LowerLeg_R", "Foot_R", "Toes_R"};
}

}  // namespace mocapfill::testing
