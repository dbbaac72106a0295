// Registers the algorithm node types (fill, filter, texture, pca_build, pca_fit, pca_edit).
// Nodes that touch files (import, database, pca_model, export) are the converter's
// (library/pipeline/file_nodes.h).
#pragma once

#include "processing/graph/node_registry.h"

namespace mocapfill::graph {

Status RegisterProcessingNodes(NodeRegistry& registry);

}  // namespace mocapfill::graph
