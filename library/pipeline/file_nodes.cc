#include "library/pipeline/file_nodes.h"

#include "library/database_loading.h"
#include "formats/file_io.h"
#include "formats/motion_io.h"
#include "formats/pca/pca_file.h"
#include "processing/graph/nodes/node_support.h"
#include "processing/graph/processing_nodes.h"
#include "formats/units_axes.h"

namespace mocapfill {

namespace {

using graph::IntOption;
using graph::Node;
using graph::NodeInputs;
using graph::NodeOptions;
using graph::NodeTypeSpec;
using graph::NumberOption;
using graph::OptionSpec;
using graph::OptionType;
using graph::OptionValue;
using graph::PortSpec;
using graph::PortType;
using graph::RunContext;
using graph::StringOption;
using graph::Value;

// A required path option whose extension is checked while the graph is validated.
OptionSpec PathOption(std::string name, std::string doc, bool (*extension_ok)(const std::string&),
                      std::string expected) {
  OptionSpec spec;
  spec.name = std::move(name);
  spec.type = OptionType::kPath;
  spec.required = true;
  spec.doc = std::move(doc);
  if (extension_ok)
    spec.check = [extension_ok, expected](const OptionValue& v) {
      if (extension_ok(v.text)) return OkStatus();
      return InvalidArgument("expected " + expected + ", got \"" + v.text + "\"");
    };
  return spec;
}

bool IsPcaExtension(const std::string& path) { return LowerExtension(path) == ".pca"; }

OptionSpec UnitOption() {
  return StringOption("unit", "auto", UnitChoices(), "length unit of the source");
}
OptionSpec UpOption() { return StringOption("up", "auto", {"auto", "y", "z"}, "up axis of the source"); }

class ImportNode : public Node {
 public:
  ImportNode(std::string path, ImportOptions options) : path_(std::move(path)), options_(std::move(options)) {}
  Result<Value> Run(const NodeInputs&, RunContext& context) const override {
    ASSIGN_OR_RETURN(Scene scene, ImportFile(path_, options_));
    for (const std::string& w : scene.warnings) context.warnings.push_back(path_ + ": " + w);
    return Value(std::shared_ptr<const Scene>(std::make_shared<Scene>(std::move(scene))));
  }

 private:
  std::string path_;
  ImportOptions options_;
};

Result<std::unique_ptr<Node>> CreateImport(const NodeOptions& o) {
  ImportOptions options;
  options.unit = o.String("unit");
  options.up = o.String("up");
  options.rate_hz = o.Number("rate_hz");
  options.animation = o.String("animation");
  options.strict = o.Bool("strict");
  return std::unique_ptr<Node>(new ImportNode(o.String("path"), options));
}

NodeTypeSpec ImportSpec() {
  NodeTypeSpec spec;
  spec.type = "import";
  spec.summary = "Read a motion file (.bvh .gltf .glb .fbx)";
  spec.role = graph::NodeRole::kSource;
  spec.output = PortSpec{"motion", PortType::kMotion, false, "the file's skeleton, animations, meshes and skins"};
  spec.options = {
      PathOption("path", "motion file to read", IsImportExtension, "a .bvh, .gltf, .glb or .fbx file"),
      UnitOption(),
      UpOption(),
      NumberOption("rate_hz", 0.0, 0.0, false, std::nullopt, "Hz", "sampling rate of keyed sources (0 = detect)"),
      StringOption("animation", "", {}, "glTF/FBX animation by name or index (empty = every animation)"),
      graph::BoolOption("strict", false, "recoverable import warnings are errors"),
  };
  spec.create = CreateImport;
  return spec;
}

class DatabaseNode : public Node {
 public:
  DatabaseNode(std::string path, DatabaseBuildOptions flags, DatabaseLoader load)
      : path_(std::move(path)), flags_(std::move(flags)), load_(std::move(load)) {}
  Result<Value> Run(const NodeInputs&, RunContext&) const override {
    std::vector<std::string> paths;
    if (path_ != "default") paths.push_back(path_);
    ASSIGN_OR_RETURN(MotionDatabase db, load_(paths, flags_));
    return Value(std::shared_ptr<const MotionDatabase>(std::make_shared<MotionDatabase>(std::move(db))));
  }

 private:
  std::string path_;
  DatabaseBuildOptions flags_;
  DatabaseLoader load_;
};

Result<std::unique_ptr<Node>> CreateDatabase(const NodeOptions& o, const DatabaseLoader& load) {
  DatabaseBuildOptions flags;
  flags.rate_hz = o.Number("rate_hz");
  flags.threads = o.Int("threads");
  flags.import.unit = o.String("unit");
  flags.import.up = o.String("up");
  if (o.Has("map")) flags.map = o.String("map");
  return std::unique_ptr<Node>(new DatabaseNode(o.String("path"), flags, load));
}

NodeTypeSpec DatabaseSpec(DatabaseLoader load) {
  NodeTypeSpec spec;
  spec.type = "database";
  spec.summary = "Load a motion database: an .mfdb file, motion files in a folder, or the embedded default";
  spec.role = graph::NodeRole::kSource;
  spec.output = PortSpec{"database", PortType::kDatabase, false, "the motion database"};
  OptionSpec path = PathOption("path", "\"default\" (embedded database), an .mfdb file, or a motion file or folder", nullptr, "");
  path.required = false;
  path.default_value = OptionValue::String("default");
  path.choices = {"default"};
  OptionSpec map = PathOption("map", "JSON joint-name map {\"source name\": \"database name\"} (none by default)", nullptr, "");
  map.required = false;
  spec.options = {
      path,
      NumberOption("rate_hz", 30.0, 0.0, true, 1000.0, "Hz", "working rate when building from motion files"),
      IntOption("threads", 0, 0, std::nullopt, "import and build threads (0 = all cores)"),
      UnitOption(),
      UpOption(),
      map,
  };
  spec.create = [load = std::move(load)](const NodeOptions& o) { return CreateDatabase(o, load); };
  return spec;
}

class PcaModelNode : public Node {
 public:
  explicit PcaModelNode(std::string path) : path_(std::move(path)) {}
  Result<Value> Run(const NodeInputs&, RunContext&) const override {
    ASSIGN_OR_RETURN(PcaModel model, ReadPcaModel(path_));
    return Value(std::shared_ptr<const PcaModel>(std::make_shared<PcaModel>(std::move(model))));
  }

 private:
  std::string path_;
};

NodeTypeSpec PcaModelSpec() {
  NodeTypeSpec spec;
  spec.type = "pca_model";
  spec.summary = "Read a PCA model file (.pca, written by `mocapfill pca build`)";
  spec.role = graph::NodeRole::kSource;
  spec.output = PortSpec{"model", PortType::kPcaModel, false, "the PCA model"};
  spec.options = {PathOption("path", "model file to read", IsPcaExtension, "a .pca file")};
  spec.create = [](const NodeOptions& o) -> Result<std::unique_ptr<Node>> {
    return std::unique_ptr<Node>(new PcaModelNode(o.String("path")));
  };
  return spec;
}

class ExportNode : public Node {
 public:
  ExportNode(std::string path, ExportOptions options) : path_(std::move(path)), options_(std::move(options)) {}
  Result<Value> Run(const NodeInputs& inputs, RunContext&) const override {
    RETURN_IF_ERROR(ExportFile(inputs.Motion("motion"), path_, options_));
    return Value(std::shared_ptr<const Scene>());  // a sink: nothing flows on
  }

 private:
  std::string path_;
  ExportOptions options_;
};

NodeTypeSpec ExportSpec() {
  NodeTypeSpec spec;
  spec.type = "export";
  spec.summary = "Write a motion to a file (.glb .gltf .bvh)";
  spec.role = graph::NodeRole::kSink;
  spec.inputs = {{"motion", PortType::kMotion, false, "motion to write"}};
  spec.options = {
      PathOption("path", "output file; written atomically", IsExportExtension, "a .glb, .gltf or .bvh file"),
      StringOption("unit", "auto", UnitChoices(), "BVH output unit (auto = the source's)"),
      graph::BoolOption("pretty", true, "pretty-print the JSON of .gltf output"),
      StringOption("skeleton", "skin", {"nodes", "skin", "mesh"},
                   "glTF of a motion without a skinned mesh: bare nodes, a skin over the joints, or a skin and a "
                   "stick-figure mesh"),
      StringOption("bvh_layout", "source", {"source", "standard"},
                   "BVH channels: the source's, or standard (rotations everywhere, positions only where they move)"),
  };
  spec.create = [](const NodeOptions& o) -> Result<std::unique_ptr<Node>> {
    ExportOptions options;
    options.unit = o.String("unit");
    options.pretty = o.Bool("pretty");
    options.gltf_skeleton = *ParseGltfSkeleton(o.String("skeleton"));
    options.bvh_layout = *ParseBvhLayout(o.String("bvh_layout"));
    return std::unique_ptr<Node>(new ExportNode(o.String("path"), options));
  };
  return spec;
}

}  // namespace

Status RegisterFileNodes(graph::NodeRegistry& registry, DatabaseLoader load) {
  if (!load)
    load = [](const std::vector<std::string>& paths, const DatabaseBuildOptions& options) {
      return LoadDatabase(paths, options, {});
    };
  for (NodeTypeSpec spec : {ImportSpec(), DatabaseSpec(std::move(load)), PcaModelSpec(), ExportSpec()})
    RETURN_IF_ERROR(registry.Register(std::move(spec)));
  return OkStatus();
}

Result<graph::NodeRegistry> MakePipelineRegistry(DatabaseLoader load) {
  graph::NodeRegistry registry;
  RETURN_IF_ERROR(RegisterFileNodes(registry, std::move(load)));
  RETURN_IF_ERROR(graph::RegisterProcessingNodes(registry));
  return registry;
}

}  // namespace mocapfill
