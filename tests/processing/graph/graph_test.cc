// The graph core: whole-graph validation (every rejection names node, type and option or
// input), topological order, defaults, and runs on a shipped BVH through the filter node.
#include <gtest/gtest.h>

#include <cmath>

#include "formats/motion_io.h"
#include "processing/core/rotation.h"
#include "processing/filtering/motion_filter.h"
#include "processing/graph/graph.h"
#include "processing/graph/nodes/node_support.h"
#include "processing/graph/processing_nodes.h"
#include "tests/support/test_paths.h"

namespace mocapfill::graph {
namespace {

using V = OptionValue;

const char* kWalk = "bvh/bandai_walk_normal_001_short.bvh";
constexpr double kIdentityToleranceRad = 1e-9;  // unit gains reproduce the clip (motion_filter.h)

// A source reading a shipped fixture (the graph core itself knows nothing of files).
class FixtureNode : public Node {
 public:
  explicit FixtureNode(std::string file) : file_(std::move(file)) {}
  Result<Value> Run(const NodeInputs&, RunContext&) const override {
    ASSIGN_OR_RETURN(Scene scene, ImportFile(testing::FixturePath(file_)));
    return Value(std::shared_ptr<const Scene>(std::make_shared<Scene>(std::move(scene))));
  }

 private:
  std::string file_;
};

// A sink remembering what it received.
class SinkNode : public Node {
 public:
  explicit SinkNode(std::shared_ptr<std::vector<Scene>> received) : received_(std::move(received)) {}
  Result<Value> Run(const NodeInputs& inputs, RunContext& context) const override {
    received_->push_back(inputs.Motion("motion"));
    context.warnings.push_back("received");
    return Value(std::shared_ptr<const Scene>());
  }

 private:
  std::shared_ptr<std::vector<Scene>> received_;
};

class FailNode : public Node {
 public:
  Result<Value> Run(const NodeInputs&, RunContext&) const override { return NumericalFailure("diverged"); }
};

struct TestRegistry {
  NodeRegistry registry;
  std::shared_ptr<std::vector<Scene>> received = std::make_shared<std::vector<Scene>>();

  TestRegistry() {
    EXPECT_TRUE(RegisterProcessingNodes(registry).ok());
    NodeTypeSpec fixture;
    fixture.type = "fixture";
    fixture.role = NodeRole::kSource;
    fixture.output = PortSpec{"motion", PortType::kMotion, false, ""};
    OptionSpec file = StringOption("file", "", {}, "fixture path");
    file.default_value = V();
    file.required = true;
    fixture.options = {file};
    fixture.create = [](const NodeOptions& o) -> Result<std::unique_ptr<Node>> {
      return std::unique_ptr<Node>(new FixtureNode(o.String("file")));
    };
    EXPECT_TRUE(registry.Register(fixture).ok());
    NodeTypeSpec sink;
    sink.type = "sink";
    sink.role = NodeRole::kSink;
    sink.inputs = {{"motion", PortType::kMotion, false, "motion"}};
    sink.create = [r = received](const NodeOptions&) -> Result<std::unique_ptr<Node>> {
      return std::unique_ptr<Node>(new SinkNode(r));
    };
    EXPECT_TRUE(registry.Register(sink).ok());
    NodeTypeSpec fail = sink;
    fail.type = "fail";
    fail.output = PortSpec{"motion", PortType::kMotion, false, ""};
    fail.create = [](const NodeOptions&) -> Result<std::unique_ptr<Node>> { return std::unique_ptr<Node>(new FailNode); };
    EXPECT_TRUE(registry.Register(fail).ok());
  }
};

NodeConfig Make(std::string id, std::string type, std::vector<std::pair<std::string, std::string>> inputs = {},
                std::vector<std::pair<std::string, OptionValue>> options = {}) {
  return NodeConfig{std::move(id), std::move(type), std::move(inputs), std::move(options)};
}

// walk -> eq (filter) -> out (sink).
GraphConfig WalkFilterSink(std::vector<std::pair<std::string, OptionValue>> filter_options = {}) {
  GraphConfig config;
  config.nodes = {Make("walk", "fixture", {}, {{"file", V::String(kWalk)}}),
                  Make("eq", "filter", {{"motion", "walk"}}, std::move(filter_options)),
                  Make("out", "sink", {{"motion", "eq"}})};
  return config;
}

std::string BuildError(const GraphConfig& config) {
  TestRegistry t;
  Result<Graph> graph = Graph::Build(config, t.registry);
  EXPECT_FALSE(graph.ok());
  if (graph.ok()) return "";
  EXPECT_EQ(graph.status().code(), ErrorCode::kInvalidArgument);
  return graph.status().message();
}

TEST(GraphBuild, OrdersNodesTopologicallyAndFillsDefaults) {
  TestRegistry t;
  GraphConfig config = WalkFilterSink();
  std::swap(config.nodes[0], config.nodes[2]);  // the file lists the sink first
  Result<Graph> graph = Graph::Build(config, t.registry);
  ASSERT_TRUE(graph.ok()) << graph.status().message();
  ASSERT_EQ(graph->plan().size(), 3u);
  EXPECT_EQ(graph->plan()[0].id, "walk");
  EXPECT_EQ(graph->plan()[1].id, "eq");
  EXPECT_EQ(graph->plan()[2].id, "out");
  EXPECT_EQ(graph->plan()[2].inputs, (std::vector<std::pair<std::string, int>>{{"motion", 1}}));
  const NodeOptions& eq = graph->plan()[1].options;
  EXPECT_EQ(eq.Number("residual_gain"), 1.0);
  EXPECT_EQ(eq.Int("levels"), 0);
  EXPECT_TRUE(eq.NumberList("gains").empty());
}

TEST(GraphBuild, SinksRunAfterEveryOtherNode) {
  TestRegistry t;
  GraphConfig config;
  config.nodes = {Make("walk", "fixture", {}, {{"file", V::String(kWalk)}}), Make("raw", "sink", {{"motion", "walk"}}),
                  Make("eq", "filter", {{"motion", "walk"}}), Make("out", "sink", {{"motion", "eq"}})};
  Result<Graph> graph = Graph::Build(config, t.registry);
  ASSERT_TRUE(graph.ok()) << graph.status().message();
  std::vector<std::string> order;
  for (const PlannedNode& node : graph->plan()) order.push_back(node.id);
  EXPECT_EQ(order, (std::vector<std::string>{"walk", "eq", "raw", "out"}));
}

TEST(GraphBuild, RejectsUnknownNodeType) {
  GraphConfig config = WalkFilterSink();
  config.nodes[1].type = "filtre";
  const std::string m = BuildError(config);
  EXPECT_NE(m.find("node \"eq\" (filtre): unknown node type \"filtre\" (known: "), std::string::npos) << m;
  EXPECT_NE(m.find("pca_edit"), std::string::npos) << m;
}

TEST(GraphBuild, RejectsUnknownOptionListingTheKnownOnes) {
  const std::string m = BuildError(WalkFilterSink({{"gain", V::Array({V::Integer(2)})}}));
  EXPECT_EQ(m, "node \"eq\" (filter): option \"gain\": unknown option (filter has: gains, residual_gain, joints, levels, periodic)");
}

TEST(GraphBuild, RejectsWrongOptionType) {
  const std::string m = BuildError(WalkFilterSink({{"levels", V::String("four")}}));
  EXPECT_EQ(m, "node \"eq\" (filter): option \"levels\": expected an integer in [0, 16], got \"four\"");
}

TEST(GraphBuild, RejectsOutOfRangeValue) {
  const std::string m = BuildError(WalkFilterSink({{"gains", V::Array({V::Integer(1), V::Integer(-2)})}}));
  EXPECT_EQ(m, "node \"eq\" (filter): option \"gains\": [1]: expected a number in [0, 10], got -2");
}

TEST(GraphBuild, RejectsMissingRequiredOption) {
  GraphConfig config = WalkFilterSink();
  config.nodes[0].options.clear();
  EXPECT_EQ(BuildError(config), "node \"walk\" (fixture): option \"file\": required (fixture path)");
}

TEST(GraphBuild, FillMethodsComeFromParseFillMethod) {
  GraphConfig config = WalkFilterSink();
  config.nodes.push_back(Make("fill", "fill", {{"sketch", "walk"}}, {{"method", V::String("foo")}}));
  const std::string m = BuildError(config);
  EXPECT_NE(m.find("node \"fill\" (fill): option \"method\": unknown method 'foo' (expected hierarchical"),
            std::string::npos)
      << m;
  // Both problems of the node are reported, not only the first.
  EXPECT_NE(m.find("node \"fill\" (fill): input \"database\": missing (a database is required"), std::string::npos) << m;
}

TEST(GraphBuild, RejectsMissingInputPort) {
  GraphConfig config = WalkFilterSink();
  config.nodes[2].inputs.clear();
  const std::string m = BuildError(config);
  EXPECT_EQ(m, "node \"out\" (sink): input \"motion\": missing (a motion is required: motion)");
}

TEST(GraphBuild, RejectsInputNamingAnUnknownNode) {
  GraphConfig config = WalkFilterSink();
  config.nodes[2].inputs = {{"motion", "qe"}};
  EXPECT_EQ(BuildError(config), "node \"out\" (sink): input \"motion\": no node \"qe\" in the pipeline");
}

TEST(GraphBuild, RejectsUnknownInputPort) {
  GraphConfig config = WalkFilterSink();
  config.nodes[1].inputs.push_back({"clip", "walk"});
  EXPECT_EQ(BuildError(config), "node \"eq\" (filter): input \"clip\": unknown port (filter has: motion, database)");
}

TEST(GraphBuild, RejectsWrongPortType) {
  GraphConfig config = WalkFilterSink();
  config.nodes.push_back(Make("model", "pca_build", {{"database", "walk"}}));
  EXPECT_EQ(BuildError(config),
            "node \"model\" (pca_build): input \"database\": expects a database, node \"walk\" (fixture) gives a motion");
}

TEST(GraphBuild, RejectsInputFromANodeWithoutOutput) {
  GraphConfig config = WalkFilterSink();
  config.nodes.push_back(Make("again", "sink", {{"motion", "out"}}));
  EXPECT_EQ(BuildError(config), "node \"again\" (sink): input \"motion\": node \"out\" (sink) has no output");
}

TEST(GraphBuild, RejectsDuplicateId) {
  GraphConfig config = WalkFilterSink();
  config.nodes[2].id = "eq";
  const std::string m = BuildError(config);
  EXPECT_NE(m.find("node \"eq\" (sink): \"id\": duplicate id"), std::string::npos) << m;
}

TEST(GraphBuild, RejectsCycles) {
  GraphConfig config = WalkFilterSink();
  config.nodes.push_back(Make("a", "filter", {{"motion", "b"}}));
  config.nodes.push_back(Make("b", "filter", {{"motion", "a"}}));
  const std::string m = BuildError(config);
  EXPECT_NE(m.find("node \"a\" (filter): is part of a cycle"), std::string::npos) << m;
  EXPECT_NE(m.find("node \"b\" (filter): is part of a cycle"), std::string::npos) << m;
  EXPECT_EQ(m.find("node \"eq\""), std::string::npos) << m;  // the valid part is not blamed
  // A node fed by the cycle is not on it, and is told so.
  config.nodes.push_back(Make("after", "sink", {{"motion", "b"}}));
  const std::string m2 = BuildError(config);
  EXPECT_NE(m2.find("node \"after\" (sink): depends on a cycle"), std::string::npos) << m2;
  EXPECT_EQ(m2.find("node \"after\" (sink): is part of a cycle"), std::string::npos) << m2;
}

TEST(GraphBuild, RejectsOtherVersionsAndEmptyGraphs) {
  GraphConfig config = WalkFilterSink();
  config.version = 2;
  EXPECT_EQ(BuildError(config), "\"version\": expected 1, got 2");
  EXPECT_EQ(BuildError(GraphConfig{}), "\"nodes\": the pipeline has no node");
}

TEST(GraphBuild, FactoriesCheckWhatSpecsCannot) {
  // A pca_edit dial beyond max_abs_sigmas: a combination of two options.
  GraphConfig config = WalkFilterSink();
  config.nodes.push_back(Make("edit", "pca_edit", {{"motion", "walk"}, {"model", "walk"}},
                              {{"components", V::Object({"x"}, {V::Integer(1)})}}));
  const std::string m = BuildError(config);
  EXPECT_NE(m.find("node \"edit\" (pca_edit): input \"model\": expects a pca_model"), std::string::npos) << m;
  config.nodes.back().inputs = {{"motion", "walk"}, {"model", "model"}};
  config.nodes.push_back(Make("model", "pca_build", {{"database", "walk"}}));
  const std::string m2 = BuildError(config);
  EXPECT_NE(m2.find("option \"components\": key \"x\": expected a component number >= 1"), std::string::npos) << m2;
}

double MaxAngleRad(const MotionClip& a, const MotionClip& b) {
  double worst = 0.0;
  for (size_t i = 0; i < a.rotations.size(); ++i) worst = std::max(worst, a.rotations[i].angularDistance(b.rotations[i]));
  return worst;
}

TEST(GraphRun, UnitGainsReproduceTheClipAndGainsMatchTheFilterFunction) {
  TestRegistry t;
  Result<Graph> identity = Graph::Build(WalkFilterSink(), t.registry);
  ASSERT_TRUE(identity.ok()) << identity.status().message();
  GraphRun run = identity->Run();
  ASSERT_TRUE(run.status.ok()) << run.status.message();
  ASSERT_EQ(run.nodes.size(), 3u);
  EXPECT_EQ(run.nodes[2].warnings, std::vector<std::string>{"received"});
  Result<Scene> walk = ImportFile(testing::FixturePath(kWalk));
  ASSERT_TRUE(walk.ok());
  ASSERT_EQ(t.received->size(), 1u);
  const MotionClip& same = (*t.received)[0].clips[0];
  ASSERT_EQ(same.num_frames, walk->clips[0].num_frames);
  EXPECT_LT(MaxAngleRad(same, walk->clips[0]), kIdentityToleranceRad);

  Result<Graph> boosted = Graph::Build(WalkFilterSink({{"gains", V::Array({V::Integer(1), V::Number(1.5, false)})}}),
                                       t.registry);
  ASSERT_TRUE(boosted.ok());
  ASSERT_TRUE(boosted->Run().status.ok());
  MultiresFilterOptions options;
  options.gains.band_gains = {1.0, 1.5};
  Result<MotionClip> direct = MultiresFilter(walk->skeleton, walk->clips[0], options);
  ASSERT_TRUE(direct.ok());
  const MotionClip& via_graph = (*t.received)[1].clips[0];
  EXPECT_EQ(MaxAngleRad(via_graph, *direct), 0.0);  // the node is the function, nothing else
  EXPECT_GT(MaxAngleRad(via_graph, walk->clips[0]), 0.1 * kPi / 180.0);  // and it did change the walk
}

TEST(GraphRun, StopsAtTheFirstFailureNamingTheNode) {
  TestRegistry t;
  GraphConfig config = WalkFilterSink();
  config.nodes[1] = Make("boom", "fail", {{"motion", "walk"}});
  config.nodes[2].inputs = {{"motion", "boom"}};
  Result<Graph> graph = Graph::Build(config, t.registry);
  ASSERT_TRUE(graph.ok()) << graph.status().message();
  const GraphRun run = graph->Run();
  EXPECT_EQ(run.status.code(), ErrorCode::kNumericalFailure);
  EXPECT_EQ(run.status.message(), "node \"boom\" (fail): diverged");
  EXPECT_EQ(run.failed_node, 1);
  EXPECT_EQ(run.nodes.size(), 2u);
  EXPECT_TRUE(t.received->empty());
}

TEST(GraphRun, MotionNodesRejectAClipLessMotion) {
  // quad_skin.glb has a skeleton and no animation: the filter node says so (kInvalidData).
  TestRegistry t;
  GraphConfig config = WalkFilterSink();
  config.nodes[0].options = {{"file", V::String("gltf/quad_skin.glb")}};
  Result<Graph> graph = Graph::Build(config, t.registry);
  ASSERT_TRUE(graph.ok());
  const GraphRun run = graph->Run();
  EXPECT_EQ(run.status.code(), ErrorCode::kInvalidData);
  EXPECT_EQ(run.status.message(), "node \"eq\" (filter): motion: no animation to filter");
}

}  // namespace
}  // namespace mocapfill::graph
