// Options of the fill: the fragment methods' and baselines' options plus those
// of the PCA-based methods, as FillEngine, the `fill` verb and the pipeline's `fill` node take
// them (the graph's fill schema, processing/graph/nodes/fill_schema.h, names every one).
#pragma once

#include "processing/core/status.h"
#include "processing/hybrid/pca_method_options.h"
#include "processing/synthesis/fragment_fill_options.h"

namespace mocapfill {

// The synthesis functions take the FragmentFillOptions part.
struct FillOptions : FragmentFillOptions {
  PcaMethodOptions pca;  // `pca` and `hybrid` methods only

  // Fails with kInvalidArgument naming the field, its value and the allowed range (the PCA
  // methods' fields prefixed "pca: ").
  Status Validate() const;
};

}  // namespace mocapfill
