#include "tests/support/default_db.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "formats/motion_io.h"
#include "tests/support/test_paths.h"

namespace mocapfill::testing {

const MotionDatabase& DefaultDb() {
  static const MotionDatabase db = [] {
    MotionDatabaseBuilder builder;
    std::vector<std::string> files;
    for (const auto& e : std::filesystem::directory_iterator(FixturePath("default_db")))
      if (e.path().extension() == ".bvh") files.push_back(e.path().string());
    std::sort(files.begin(), files.end());
    for (const std::string& f : files) {
      Result<Scene> scene = ImportFile(f);
      EXPECT_TRUE(scene.ok()) << scene.status().message();
      EXPECT_TRUE(builder.Add(scene->skeleton, scene->clips[0], {{"file", f}}).ok());
    }
    Result<MotionDatabase> built = builder.Build();
    EXPECT_TRUE(built.ok()) << built.status().message();
    return std::move(*built);
  }();
  return db;
}

}  // namespace mocapfill::testing
