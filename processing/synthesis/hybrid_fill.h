// The PCA-based fill methods (issue #5; algorithms.md 5-7):
//  - `pca`: the closed-form regularised PCA fit per frame (5a.6, baseline B4);
//  - `hybrid` (thesis chapter 6, baseline B7): 1. hierarchical fragments (section 4);
//    2. the Ceres PCA fit to the sketch's keys with a guide term towards the fragment result
//    (section 6; it reconciles the independently synthesised groups with each other and with
//    the keys); 3. texturing: the fit's low bands plus the fragment result's high bands on
//    every channel, keys re-pinned (3a.6-3a.7; texture last so the prior does not smooth it
//    away); 4. optional band gains (section 2) and PCA component dials (5a.5).
// FillEngine (fill.h) runs both by method name; the functions below are the stages as
// callables for processing graphs. Clips are in the database's joint order and rate.
#pragma once

#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/motion_database.h"
#include "processing/core/pca_model.h"
#include "processing/core/status.h"
#include "processing/pca/pca_sketch.h"
#include "processing/synthesis/fill.h"
#include "processing/synthesis/fill_options.h"

namespace mocapfill {

// The whole hybrid fill. `model` may be null: a model is then built from `db` with
// options.pca.model (reported as stage "pca_model"). options.method is ignored (hybrid).
// Errors: as FillEngine::Fill.
Result<FillResult> HybridFill(const MotionDatabase& db, const MotionClip& sketch, const PcaModel* model,
                              const FillOptions& options, const std::vector<SketchPositionKey>& position_keys = {});

// Stage 3. `fitted` (the PCA fit) and `fragments` (the fragment fill) have the sketch's
// frames. Keyed channels: low bands of the fit (or of the sketch, options.pca.keyed_base)
// plus the fragment result's bands above the keys' Nyquist rate, keys re-pinned
// (options.repin_keys); synthesised channels: the fit's low bands plus the same high bands
// (options.pca.texture_synthesized). options.texture = false keeps the fit (keys still
// re-pinned). Joints on the chain from the root to a position-keyed joint keep the fit
// (neither textured nor re-pinned), so position keys survive. Root features (trajectory) come from `fragments`.
// Errors: clips that do not fit the database skeleton or each other (kInvalidArgument).
Result<MotionClip> TextureHybrid(const MotionDatabase& db, const MotionClip& sketch, const MotionClip& fitted,
                                 const MotionClip& fragments, const FillOptions& options,
                                 const std::vector<SketchPositionKey>& position_keys = {});

// Stage 4: component dials (options.pca.dials, residual kept) then band gains
// (options.pca.band_gains, about the database means). Keys are not re-pinned: edits are
// deliberate changes. With neither, returns the clip unchanged. Errors: invalid dials for
// the model, gains for bands the clip does not have (kInvalidArgument).
Result<MotionClip> EditHybrid(const MotionDatabase& db, const PcaModel& model, const MotionClip& clip,
                              const PcaMethodOptions& options);

}  // namespace mocapfill
