// Pipeline files: JSON schema errors, relative paths, --set overrides.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "library/pipeline/file_nodes.h"
#include "library/pipeline/pipeline_file.h"
#include "tests/support/test_paths.h"

namespace mocapfill::cli {
namespace {

std::string ParseError(const std::string& text) {
  Result<PipelineFile> file = ParsePipelineJson(text);
  EXPECT_FALSE(file.ok());
  if (file.ok()) return "";
  EXPECT_EQ(file.status().code(), ErrorCode::kInvalidArgument);
  return file.status().message();
}

TEST(PipelineJson, ReadsNodesInputsAndTypedOptions) {
  Result<PipelineFile> file = ParsePipelineJson(R"({"version": 1, "description": "d", "nodes": [
      {"id": "a", "type": "import", "options": {"path": "x.bvh", "rate_hz": 30, "gains": [1, 1.5], "strict": true}},
      {"id": "b", "type": "export", "inputs": {"motion": "a"}, "comment": "free text"}]})");
  ASSERT_TRUE(file.ok()) << file.status().message();
  EXPECT_EQ(file->description, "d");
  ASSERT_EQ(file->config.nodes.size(), 2u);
  const graph::NodeConfig& a = file->config.nodes[0];
  ASSERT_EQ(a.options.size(), 4u);
  EXPECT_EQ(a.options[0].second.text, "x.bvh");
  EXPECT_TRUE(a.options[1].second.is_integer);
  EXPECT_EQ(a.options[1].second.number, 30.0);
  EXPECT_FALSE(a.options[2].second.items[1].is_integer);
  EXPECT_TRUE(a.options[3].second.boolean);
  EXPECT_EQ(file->config.nodes[1].inputs, (std::vector<std::pair<std::string, std::string>>{{"motion", "a"}}));
}

TEST(PipelineJson, SchemaErrorsNameTheFieldAndTheNode) {
  EXPECT_NE(ParseError("{\"version\": 1,\n \"nodes\": [}").find("invalid JSON: parse error at line 2, column 12"),
            std::string::npos);
  EXPECT_EQ(ParseError(R"({"nodes": []})"), "\"version\" is missing (this build reads version 1)");
  EXPECT_EQ(ParseError(R"({"version": "1", "nodes": []})"), "\"version\": expected an integer (1)");
  EXPECT_EQ(ParseError(R"({"version": 1, "node": []})"), "unknown field \"node\" (expected version, description, nodes)");
  EXPECT_EQ(ParseError(R"({"version": 1, "nodes": [{"id": "a"}]})"), "node \"a\": \"type\" is missing");
  EXPECT_EQ(ParseError(R"({"version": 1, "nodes": [{"type": "import"}]})"), "node #1: \"id\" is missing");
  EXPECT_EQ(ParseError(R"({"version": 1, "nodes": [{"id": "a", "type": "t", "inputs": {"m": 3}}]})"),
            "node \"a\": input \"m\": expected the id of a node (a string)");
  EXPECT_EQ(ParseError(R"({"version": 1, "nodes": [{"id": "a", "type": "t", "options": [1]}]})"),
            "node \"a\": \"options\": expected an object {option: value}");
  EXPECT_EQ(ParseError(R"({"version": 1, "nodes": [{"id": "a", "type": "t", "input": {}}]})"),
            "node \"a\": unknown field \"input\" (expected id, type, inputs, options, comment)");
}

TEST(PipelineJson, RelativePathsResolveAgainstThePipelineFolder) {
  const std::string dir = testing::ScratchDir("pipeline_paths");
  std::filesystem::create_directories(dir + "/sub");
  const std::string path = dir + "/sub/p.json";
  std::ofstream(path) << R"({"version": 1, "nodes": [
      {"id": "a", "type": "import", "options": {"path": "../walk.bvh", "unit": "cm"}},
      {"id": "db", "type": "database", "options": {"path": "default"}},
      {"id": "abs", "type": "import", "options": {"path": "/tmp/x.bvh"}}]})";
  Result<graph::NodeRegistry> registry = MakePipelineRegistry();
  ASSERT_TRUE(registry.ok()) << registry.status().message();
  Result<PipelineFile> file = ReadPipelineFile(path, *registry);
  ASSERT_TRUE(file.ok()) << file.status().message();
  EXPECT_EQ(file->config.nodes[0].options[0].second.text, dir + "/walk.bvh");
  EXPECT_EQ(file->config.nodes[0].options[1].second.text, "cm");  // not a path option
  EXPECT_EQ(file->config.nodes[1].options[0].second.text, "default");  // a keyword, not a path
  EXPECT_EQ(file->config.nodes[2].options[0].second.text, "/tmp/x.bvh");
  Result<PipelineFile> missing = ReadPipelineFile(dir + "/none.json", *registry);
  EXPECT_EQ(missing.status().code(), ErrorCode::kIoError);
}

TEST(PipelineOverrides, SetTakesJsonOrPlainText) {
  Result<PipelineFile> file = ParsePipelineJson(
      R"({"version": 1, "nodes": [{"id": "fill", "type": "fill", "options": {"method": "hierarchical"}}]})");
  ASSERT_TRUE(file.ok());
  ASSERT_TRUE(ApplyOverrides({"fill.method=nn", "fill.candidates=64", "fill.keep=[\"Hips\"]", "fill.texture=false"},
                             file->config)
                  .ok());
  const auto& options = file->config.nodes[0].options;
  ASSERT_EQ(options.size(), 4u);
  EXPECT_EQ(options[0].second.text, "nn");  // replaced in place
  EXPECT_TRUE(options[1].second.is_integer);
  EXPECT_EQ(options[1].second.number, 64.0);
  EXPECT_EQ(options[2].second.items.at(0).text, "Hips");
  EXPECT_FALSE(options[3].second.boolean);
  EXPECT_EQ(ApplyOverrides({"fil.method=nn"}, file->config).message(),
            "--set \"fil.method=nn\": no node \"fil\" in the pipeline");
  EXPECT_EQ(ApplyOverrides({"method=nn"}, file->config).message(),
            "--set \"method=nn\": expected node.option=value, e.g. fill.method=nn");
}

}  // namespace
}  // namespace mocapfill::cli
