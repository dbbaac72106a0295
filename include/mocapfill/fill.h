// Filling a sketch (the thesis's task): the sketch's keyed joints at their key frames, on
// any humanoid rig and at any rate, completed from a motion capture database into a whole
// animation of the same rig, keys kept exactly.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "mocapfill/database.h"
#include "mocapfill/export.h"
#include "mocapfill/pca.h"
#include "mocapfill/scene.h"

namespace mocapfill::api {

struct FillOptions {
  std::string method = "hierarchical";  // hierarchical, fragment, nn, mean, pca, hybrid
  // Rig map overrides: sketch joint -> canonical bone (VRM name) or database joint; "" unmaps.
  std::map<std::string, std::string> map;
  std::string rest = "auto";     // the sketch rig's rest pose: auto, bind, zero, mean, first-frame
  double output_rate_hz = 0.0;   // 0 = the sketch's own rate
  std::vector<std::string> keep;           // only these joints stay keyed
  std::vector<std::string> synthesize;     // joints synthesised even when keyed
  std::vector<std::string> position_keys;  // translation keys that are world targets (hybrid)
  bool plant_feet = true;        // hold feet standing at two consecutive keys between them
  bool texture = true;           // add captured detail to the keyed joints
  std::string coverage = "blend";  // blend: poorly covered stretches fade toward the mean; warn: only report
  const PcaModel* pca_model = nullptr;  // pca/hybrid: nullptr = built from the database
  int threads = 0;                      // 0 = every core
  // Any other option of the fill by its pipeline name, as text: {"candidates", "64"},
  // {"coverage_poor", "0.06"}, {"dial", "1=+1.5"}, {"gains", "1,1,1.5"} (`mocapfill run
  // --list-nodes` lists them under "fill"). Checked as the command line checks its flags;
  // naming an option the fields above set is an error ("given twice").
  std::map<std::string, std::string> more;
};

struct FillResult {
  Scene scene;              // the sketch's scene (nodes, meshes, skins) with the filled clip
  std::string report_json;  // what `mocapfill fill --report` writes
  // Rotation key errors of `scene`'s clip at the sketch's exact key times (degrees).
  double key_error_mean_deg = 0.0;
  double key_error_max_deg = 0.0;
  std::vector<std::string> warnings;  // e.g. stretches the database covers poorly
};

// Fills the first clip of `sketch`. Throws Error: kInvalidInput for a sketch without keys,
// a rig that is not humanoid or a bad map; kUsage for bad options; kProcessing when the
// fill fails.
MOCAPFILL_API FillResult Fill(const Scene& sketch, const Database& database, const FillOptions& options = {});

}  // namespace mocapfill::api
