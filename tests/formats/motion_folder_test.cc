#include "formats/mfdb/motion_folder.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "formats/file_io.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

TEST(MotionFolder, LabelsComeFromTheFileNameJsonAndCfgLists) {
  const std::string root = testing::ScratchDir("motion_folder_labels");
  std::filesystem::create_directories(root + "/data");
  std::filesystem::create_directories(root + "/cfg");
  ASSERT_TRUE(WriteFileAtomic(root + "/cfg/content_label.txt", "dataset-1_walk\ndataset-1_walk-back\n").ok());
  ASSERT_TRUE(WriteFileAtomic(root + "/cfg/style_label.txt", "dataset-1_normal\ndataset-1_not-confident\n").ok());
  const std::string clip = root + "/data/dataset-1_walk-back_not-confident_002.bvh";
  ASSERT_TRUE(WriteFileAtomic(clip, "not read by ReadClipLabels").ok());
  ASSERT_TRUE(WriteFileAtomic(root + "/data/dataset-1_walk-back_not-confident_002.json",
                              "{\"content\": 1, \"style\": 1, \"take\": \"B\"}").ok());
  Result<std::map<std::string, std::string>> labels = ReadClipLabels(clip);
  ASSERT_TRUE(labels.ok()) << labels.status().message();
  EXPECT_EQ(labels->at("content"), "walk-back");
  EXPECT_EQ(labels->at("style"), "not-confident");
  EXPECT_EQ(labels->at("id"), "002");
  EXPECT_EQ(labels->at("content_index"), "1");
  EXPECT_EQ(labels->at("take"), "B");
  EXPECT_EQ(labels->at("name"), "dataset-1_walk-back_not-confident_002");
  EXPECT_EQ(labels->at("file"), clip);

  const std::string plain = root + "/data/jump.bvh";
  ASSERT_TRUE(WriteFileAtomic(plain, "x").ok());
  labels = ReadClipLabels(plain);
  ASSERT_TRUE(labels.ok());
  EXPECT_EQ(labels->count("content"), 0u);

  ASSERT_TRUE(WriteFileAtomic(root + "/data/jump.json", "{broken").ok());
  EXPECT_EQ(ReadClipLabels(plain).status().code(), ErrorCode::kInvalidData);
}

TEST(MotionFolder, ListsImportableFilesSortedAndRejectsMissingPaths) {
  const std::string root = testing::ScratchDir("motion_folder_list");
  std::filesystem::create_directories(root + "/sub");
  for (const char* name : {"/b.bvh", "/a.glb", "/notes.txt", "/sub/c.fbx", "/a.json"})
    ASSERT_TRUE(WriteFileAtomic(root + name, "x").ok());
  Result<std::vector<std::string>> files = ListMotionFiles({root, root + "/b.bvh"});
  ASSERT_TRUE(files.ok());
  EXPECT_EQ(*files, (std::vector<std::string>{root + "/a.glb", root + "/b.bvh", root + "/sub/c.fbx"}));
  EXPECT_EQ(ListMotionFiles({root + "/nothing"}).status().code(), ErrorCode::kIoError);
  const std::string empty = testing::ScratchDir("motion_folder_empty");
  EXPECT_EQ(ListMotionFiles({empty}).status().code(), ErrorCode::kInvalidArgument);
}

}  // namespace
}  // namespace mocapfill
