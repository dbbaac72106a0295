// Multiresolution motion filtering (Bruderlin and Williams 1995): each clip split into
// frequency bands and recombined with a gain per band.
#pragma once

#include <string>
#include <vector>

#include "mocapfill/export.h"
#include "mocapfill/scene.h"

namespace mocapfill::api {

struct FilterOptions {
  std::vector<double> gains;        // per band, highest frequency first; missing gains are 1
  double residual_gain = 1.0;       // gain of the slowly varying average pose
  int levels = 0;                   // bands; 0 = from the clip's length and rate
  std::vector<std::string> joints;  // joints to filter; empty = every joint
};

// Every clip of `scene` filtered. Throws Error (kUsage naming the option).
MOCAPFILL_API Scene Filter(const Scene& scene, const FilterOptions& options);

}  // namespace mocapfill::api
