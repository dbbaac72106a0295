// The pipeline nodes that read or write files (import, database, pca_model, export): they live
// beside the use cases because the graph core knows nothing of files. Each calls the same
// entry points as the verbs (formats/motion_io.h, library/database_loading.h, formats/pca).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "library/database_loading.h"
#include "processing/graph/node_registry.h"

namespace mocapfill {

// How the database node loads its database (paths empty: the default database): the CLI's
// shows a progress bar, the default (LoadDatabase) stays quiet.
using DatabaseLoader =
    std::function<Result<MotionDatabase>(const std::vector<std::string>& paths, const DatabaseBuildOptions& options)>;

Status RegisterFileNodes(graph::NodeRegistry& registry, DatabaseLoader load = {});

// Every node type of `mocapfill run`: the file nodes above and the algorithm nodes.
Result<graph::NodeRegistry> MakePipelineRegistry(DatabaseLoader load = {});

}  // namespace mocapfill
