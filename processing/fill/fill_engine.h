// The fill stage (issues #4, #5): completes a sketch (keyed joints plus missing ones) from a
// motion database with any method of FillOptions, by name, and reports where everything came
// from. The methods live in their own folders: the fragment methods and baselines in
// processing/synthesis, the hybrid in processing/hybrid, the PCA model and its fits in
// processing/pca. The sketch must already be on the database's rig and at its rate
// (sketch_fill/ brings a sketch on any rig there).
#pragma once

#include <memory>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/motion_database.h"
#include "processing/core/pca_model.h"
#include "processing/core/status.h"
#include "processing/core/motion_database.h"
#include "processing/fill/fill_options.h"
#include "processing/fill/fill_report.h"
#include "processing/pca/pca_model_builder.h"
#include "processing/pca/pca_sketch.h"
#include "processing/synthesis/fragment_fill_engine.h"

namespace mocapfill {

struct FillResult {
  MotionClip clip;   // database joint order and rate, every joint keyed at every frame
  FillReport report;
};

// Holds the database, caches its sketch-filtered copy between fills of sketches with the
// same keyed channels and key spacing (an evaluation fills many such sketches) and the PCA
// model it builds. Not thread-safe: one engine per thread; matching inside a fill uses
// options.threads.
class FillEngine {
 public:
  explicit FillEngine(const MotionDatabase& db);
  ~FillEngine();
  FillEngine(const FillEngine&) = delete;
  FillEngine& operator=(const FillEngine&) = delete;

  // Fills every joint the sketch does not key. Keyed joints keep the sketch's rotations
  // (textured with the matched high bands when options.texture, keys re-pinned). Errors:
  // invalid options (kInvalidArgument); a sketch that does not fit the database skeleton,
  // has no frames or no keyed joint (kInvalidData); for `pca`/`hybrid` a model that does not
  // fit the database skeleton or rate (kInvalidArgument), a failed key fit (kNumericalFailure).
  Result<FillResult> Fill(const MotionClip& sketch, const FillOptions& options);
  // As above; `position_keys` (world positions of joints, metres) are fitted by the hybrid
  // method's PCA stage (s_pos = options.pca.fit.fit.position_sigma_cm); other methods reject them.
  Result<FillResult> Fill(const MotionClip& sketch, const FillOptions& options,
                          const std::vector<SketchPositionKey>& position_keys);

  // The PCA model of the `pca` and `hybrid` methods (not owned; must outlive the engine).
  // Without one, the first such fill builds a model from the engine's database with
  // options.pca.model (in memory only; its build time is reported as stage "pca_model") and
  // keeps it for later fills: a leave-one-out fold's model sees only that fold's database.
  void SetPcaModel(const PcaModel* model) { given_model_ = model; }

 private:
  Result<const PcaModel*> Model(const FillOptions& options, FillReport& report);
  Result<FillResult> FillPca(const MotionClip& sketch, const FillOptions& options);
  Result<FillResult> FillHybrid(const MotionClip& sketch, const FillOptions& options,
                                const std::vector<SketchPositionKey>& position_keys);

  const MotionDatabase& db_;
  FragmentFillEngine fragments_;
  const PcaModel* given_model_ = nullptr;
  std::unique_ptr<PcaModel> built_model_;
  PcaModelOptions built_model_options_;
};

}  // namespace mocapfill
