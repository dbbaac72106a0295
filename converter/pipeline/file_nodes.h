// The pipeline nodes that read or write files (import, database, pca_model, export): they live
// on the converter side because the graph core knows nothing of files. Each calls the same
// entry points as the verbs (formats/motion_io.h, converter/database_arg.h, formats/pca).
#pragma once

#include "processing/graph/node_registry.h"

namespace mocapfill::cli {

Status RegisterFileNodes(graph::NodeRegistry& registry);

// Every node type of `mocapfill run`: the file nodes above and the algorithm nodes.
Result<graph::NodeRegistry> MakePipelineRegistry();

}  // namespace mocapfill::cli
