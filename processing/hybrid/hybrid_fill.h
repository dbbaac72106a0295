// The hybrid fill method (thesis chapter 6):
//  1. hierarchical fragments (thesis 4.7);
//  2. the Ceres PCA fit to the sketch's keys with a guide term towards the fragment result
//     (thesis chapter 5; it reconciles the independently synthesised groups with each other and with
//     the keys);
//  3. texturing: the fit's low bands plus the fragment result's high bands on every channel,
//     keys re-pinned (3a.6-3a.7; texture last so the prior does not smooth it away);
//  4. optional band gains (section 2) and PCA component dials (5a.5).
// FillEngine (processing/fill) runs it by method name with its fragment engine and PCA model;
// the stages are callables for processing graphs too. Clips are in the database's joint order
// and rate.
#pragma once

#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/pca_model.h"
#include "processing/core/status.h"
#include "processing/core/motion_database.h"
#include "processing/hybrid/pca_method_options.h"
#include "processing/pca/ceres_fit/pca_fit.h"
#include "processing/pca/pca_sketch.h"
#include "processing/synthesis/fragment_fill_engine.h"
#include "processing/synthesis/fragment_fill_options.h"
#include "processing/synthesis/fragment_fill_report.h"

namespace mocapfill {

struct HybridResult {
  MotionClip clip;      // database joint order and rate, every joint keyed at every frame
  SolverReport solver;  // the Ceres summary of stage 2
};

// The whole hybrid fill: stage 1 runs `fragments` with `options` (whose method is ignored:
// hierarchical), stages 2-4 fit `model` with `pca`. `position_keys` (world positions of joints,
// metres) are fitted in stage 2 (s_pos = pca.fit.fit.position_sigma_cm). Writes to `report`
// the key spacing, stage 1's sources, seams and groups, the joints and key errors, and the time
// of every stage (stage 1's as "fragments.<stage>"). Errors: as FragmentFillEngine::Fill,
// invalid `pca` options, a model that does not fit the database skeleton or rate
// (kInvalidArgument), a failed key fit (kNumericalFailure).
Result<HybridResult> HybridFill(FragmentFillEngine& fragments, const PcaModel& model, const MotionClip& sketch,
                                const FragmentFillOptions& options, const PcaMethodOptions& pca,
                                const std::vector<SketchPositionKey>& position_keys, FragmentFillReport& report);

// Stage 3. `fitted` (the PCA fit) and `fragments` (the fragment fill) have the sketch's
// frames. Keyed channels: low bands of the fit (or of the sketch, pca.keyed_base) plus the
// fragment result's bands above the keys' Nyquist rate, keys re-pinned (options.repin_keys);
// synthesised channels: the fit's low bands plus the same high bands (pca.texture_synthesized).
// options.texture = false keeps the fit (keys still re-pinned). Joints on the chain from the
// root to a position-keyed joint keep the fit (neither textured nor re-pinned), so position
// keys survive. Root features (trajectory) come from `fragments`. Errors: clips that do not
// fit the database skeleton or each other (kInvalidArgument).
Result<MotionClip> TextureHybrid(const MotionDatabase& db, const MotionClip& sketch, const MotionClip& fitted,
                                 const MotionClip& fragments, const FragmentFillOptions& options,
                                 const PcaMethodOptions& pca, const std::vector<SketchPositionKey>& position_keys = {});

// Stage 4: component dials (options.dials, residual kept) then band gains (options.band_gains,
// about the database means). Keys are not re-pinned: edits are deliberate changes. With
// neither, returns the clip unchanged. Errors: invalid dials for the model, gains for bands
// the clip does not have (kInvalidArgument).
Result<MotionClip> EditHybrid(const MotionDatabase& db, const PcaModel& model, const MotionClip& clip,
                              const PcaMethodOptions& options);

}  // namespace mocapfill
