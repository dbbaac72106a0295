#include "tests/support/default_db.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "formats/motion_io.h"
#include "processing/database/motion_database_builder.h"
#include "processing/retargeting/retarget_scene.h"
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

const MotionDatabase& BandaiDbWithout(const std::string& style) {
  static std::map<std::string, MotionDatabase> cache;
  if (auto it = cache.find(style); it != cache.end()) return it->second;
  MotionDatabaseBuilder builder;
  for (const std::string& f : CorpusFiles("bandai-namco-1/data", ".bvh")) {
    if (f.find("_" + style + "_") != std::string::npos) continue;
    Result<Scene> scene = ImportFile(f);
    EXPECT_TRUE(scene.ok()) << scene.status().message();
    EXPECT_TRUE(builder.Add(scene->skeleton, scene->clips[0], {{"file", f}}).ok());
  }
  Result<MotionDatabase> built = builder.Build();
  EXPECT_TRUE(built.ok()) << built.status().message();
  return cache.emplace(style, std::move(*built)).first->second;
}

MotionClip ShippedSketchOnDefaultDbRig() {
  Result<Scene> sketch = ImportFile(FixturePath("sketches/walk_proud_002_legs8.glb"));
  EXPECT_TRUE(sketch.ok()) << sketch.status().message();
  if (!sketch.ok()) return {};
  Scene character;
  character.skeleton = DefaultDb().skeleton();
  // One rig on both sides: retargeting copies the rotations and keys exactly.
  Result<Scene> on_db = RetargetScene(*sketch, character);
  EXPECT_TRUE(on_db.ok()) << on_db.status().message();
  if (!on_db.ok() || on_db->clips.empty()) return {};
  return std::move(on_db->clips.front());
}

}  // namespace mocapfill::testing
