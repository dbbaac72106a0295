#include "processing/graph/processing_nodes.h"

#include "processing/graph/nodes/nodes.h"

namespace mocapfill::graph {

Status RegisterProcessingNodes(NodeRegistry& registry) {
  for (NodeTypeSpec (*spec)() : {FillNodeSpec, FilterNodeSpec, TextureNodeSpec, PcaBuildNodeSpec, PcaFitNodeSpec,
                                 PcaEditNodeSpec})
    RETURN_IF_ERROR(registry.Register(spec()));
  return OkStatus();
}

}  // namespace mocapfill::graph
