// Options of the PCA-based fill methods, `pca` (the closed-form fit per frame) and `hybrid`
// (thesis chapter 6): the model built when none is given, the fits, the
// hybrid's texturing and its optional edits. The fill's options (processing/fill) carry them
// as FillOptions::pca.
#pragma once

#include <vector>

#include "processing/core/status.h"
#include "processing/pca/closed_form_fit.h"
#include "processing/pca/pca_edit.h"
#include "processing/pca/pca_model_builder.h"
#include "processing/pca/pca_sketch.h"

namespace mocapfill {

// What a keyed channel's low bands come from in the hybrid's texturing stage.
enum class KeyedBase {
  kFit,     // the PCA fit (keys within s_key, smooth in between by the prior)
  kSketch,  // the sketch interpolated between its keys (as the hierarchical method)
};

// Options of the PCA-based methods (`pca`, `hybrid`). Units in the names.
struct PcaMethodOptions {
  // Model built in memory from the fill database when the caller gives none (FillEngine::
  // SetPcaModel): pose PCA, 95 % of the variance, at most 30 components.
  PcaModelOptions model;
  ClosedFormOptions closed_form;  // `pca`: observation noise of keyed channels (1 deg)
  // `hybrid` stage 2: the Ceres fit, guided towards the fragment result. Default: the subspace
  // variant (keys within s_key, re-pinned after texturing) with s_guide = 3 deg, the best of
  // the variants tried (docs/fill.md, "Variants tried"); the full-pose variant (fit.full_pose:
  // keyed joints held exactly, all others free under the PPCA prior) scores better on gestures
  // but its solve is several times slower. s_pos = 0.1 cm keeps position-keyed feet within
  // about half a centimetre against the guide.
  PcaSketchFitOptions fit = [] {
    PcaSketchFitOptions o;
    o.fit.guide_sigma_deg = 3.0;
    o.fit.position_sigma_cm = 0.1;
    return o;
  }();
  // `hybrid` stage 3: texture bands of the fragment result added to every synthesised
  // channel too (not only keyed ones), so the PCA prior does not smooth capture detail away.
  bool texture_synthesized = true;
  KeyedBase keyed_base = KeyedBase::kFit;
  // `hybrid` stage 4 (optional edits, applied last; keys are not re-pinned after them):
  std::vector<double> band_gains;    // Bruderlin-Williams gains, band 0 first; empty = none
  std::vector<ComponentDial> dials;  // PCA component dials in standard deviations

  Status Validate() const;
};

}  // namespace mocapfill
