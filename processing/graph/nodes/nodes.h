// The algorithm node types (processing/graph/nodes/*.cc), one spec function each; the
// registry entry point is processing/graph/processing_nodes.h.
#pragma once

#include "processing/graph/node.h"

namespace mocapfill::graph {

NodeTypeSpec FillNodeSpec();       // fill_node.cc
NodeTypeSpec FilterNodeSpec();     // filter_node.cc
NodeTypeSpec TextureNodeSpec();    // texture_node.cc
NodeTypeSpec PcaBuildNodeSpec();   // pca_nodes.cc
NodeTypeSpec PcaFitNodeSpec();     // pca_nodes.cc
NodeTypeSpec PcaEditNodeSpec();    // pca_nodes.cc

}  // namespace mocapfill::graph
