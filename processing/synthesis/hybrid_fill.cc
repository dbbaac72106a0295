#include "processing/synthesis/hybrid_fill.h"

#include <algorithm>

#include "processing/filtering/motion_filter.h"
#include "processing/pca/pca_clip.h"
#include "processing/pca/pca_edit.h"
#include "processing/pca/pca_model_builder.h"
#include "processing/synthesis/assembly.h"
#include "processing/synthesis/fill_stages.h"

namespace mocapfill {

namespace {

bool SameModelOptions(const PcaModelOptions& a, const PcaModelOptions& b) {
  return a.basis.variance_kept == b.basis.variance_kept && a.basis.max_components == b.basis.max_components &&
         a.basis.window_frames == b.basis.window_frames &&
         a.basis.window_stride_frames == b.basis.window_stride_frames && a.labels == b.labels &&
         a.root_rate_horizon_s == b.root_rate_horizon_s;
}

Status CheckClip(const MotionDatabase& db, const MotionClip& sketch, const MotionClip& clip, const char* what) {
  RETURN_IF_ERROR(clip.Validate(db.skeleton()).WithContext(what));
  if (clip.num_frames != sketch.num_frames)
    return InvalidArgument(std::string(what) + " has " + std::to_string(clip.num_frames) + " frames, the sketch " +
                           std::to_string(sketch.num_frames));
  return OkStatus();
}

// Joints from the root down to every position-keyed joint (texture would move those feet).
std::vector<std::uint8_t> PositionChains(const MotionDatabase& db, const std::vector<SketchPositionKey>& keys) {
  std::vector<std::uint8_t> hold(db.num_joints(), 0);
  for (const SketchPositionKey& key : keys) {
    const std::optional<int> j = db.skeleton().Find(key.joint);
    for (int p = j ? *j : kNoParent; p != kNoParent; p = db.skeleton().parent(p)) hold[p] = 1;
  }
  return hold;
}

std::vector<int> Channels(const std::vector<int>& joints) {
  std::vector<int> channels;
  for (int j : joints)
    for (int a = 0; a < 3; ++a) channels.push_back(3 * j + a);
  return channels;
}

// The fragment fill's report becomes the hybrid's (sources, seams, groups); its stages are
// listed under "fragments.<stage>".
void TakeFragmentReport(const FillReport& from, FillReport& to) {
  to.master_channel = from.master_channel;
  to.fragment_band = from.fragment_band;
  to.sketch_fragments = from.sketch_fragments;
  to.seams = from.seams;
  to.fragments = from.fragments;
  to.group_order = from.group_order;
  for (const StageTime& t : from.stages) to.stages.push_back({"fragments." + t.stage, t.seconds});
}

void StartReport(const MotionDatabase& db, const MotionClip& sketch, const FillOptions& options, FillReport& report) {
  report.method = FillMethodName(options.method);
  report.join = options.method == FillMethod::kHybrid ? JoinCriterionName(options.join) : "none";
  report.frames = sketch.num_frames;
  report.rate_hz = db.rate_hz();
}

}  // namespace

Result<const PcaModel*> FillEngine::Model(const FillOptions& options, FillReport& report) {
  if (given_model_ != nullptr) {
    report.pca_model_source = "given";
  } else {
    if (!built_model_ || !SameModelOptions(built_model_options_, options.pca.model)) {
      ASSIGN_OR_RETURN(PcaModel model, BuildPcaModel(db_, options.pca.model));
      built_model_ = std::make_unique<PcaModel>(std::move(model));
      built_model_options_ = options.pca.model;
    }
    report.pca_model_source = "built from the database";
  }
  const PcaModel* model = given_model_ != nullptr ? given_model_ : built_model_.get();
  report.pca_components = model->num_components();
  return model;
}

Result<FillResult> FillEngine::FillPca(const MotionClip& sketch, const FillOptions& options) {
  FillResult result;
  FillReport& report = result.report;
  StartReport(db_, sketch, options, report);
  StageTimer timer(report);
  ASSIGN_OR_RETURN(const PcaModel* model, Model(options, report));
  timer.Mark("pca_model");
  ASSIGN_OR_RETURN(const SketchSignals s, MakeSketchSignals(db_, sketch));
  report.key_spacing_frames = s.key_spacing;
  timer.Mark("prepare");
  PcaFillOptions fill;
  fill.closed_form = options.pca.closed_form;
  ASSIGN_OR_RETURN(result.clip, FillMissingJointsPca(*model, db_.skeleton(), sketch, fill));
  result.clip.MakeContinuous();
  result.clip.KeyAllFrames();
  timer.Mark("closed_form");
  ReportJoints(db_, s, sketch, result.clip, false, report);
  timer.Mark("report");
  return result;
}

Result<FillResult> FillEngine::FillHybrid(const MotionClip& sketch, const FillOptions& options,
                                          const std::vector<SketchPositionKey>& position_keys) {
  FillResult result;
  FillReport& report = result.report;
  StartReport(db_, sketch, options, report);
  StageTimer timer(report);
  ASSIGN_OR_RETURN(const PcaModel* model, Model(options, report));
  timer.Mark("pca_model");
  // 1. Hierarchical fragments (their own texture adds the lead candidates' high bands to the
  // keyed joints, which stage 3 passes on).
  FillOptions fragment_options = options;
  fragment_options.method = FillMethod::kHierarchical;
  ASSIGN_OR_RETURN(const FillResult fragments, Fill(sketch, fragment_options));
  TakeFragmentReport(fragments.report, report);
  report.key_spacing_frames = fragments.report.key_spacing_frames;
  timer.Mark("fragments");
  // 2. The Ceres fit to the keys, guided towards the fragments on the unkeyed joints.
  ASSIGN_OR_RETURN(const PcaSketchFit fitted,
                   FitSketchToKeys(*model, db_.skeleton(), sketch, position_keys, &fragments.clip, options.pca.fit));
  report.has_solver = true;
  report.solver = fitted.fit.report;
  timer.Mark("pca_fit");
  // 3. Texture and key re-pinning.
  ASSIGN_OR_RETURN(MotionClip clip, TextureHybrid(db_, sketch, fitted.clip, fragments.clip, options, position_keys));
  timer.Mark("hybrid_texture");
  // 4. Optional edits.
  ASSIGN_OR_RETURN(result.clip, EditHybrid(db_, *model, clip, options.pca));
  timer.Mark("edit");
  ASSIGN_OR_RETURN(const SketchSignals s, MakeSketchSignals(db_, sketch));
  ReportJoints(db_, s, sketch, result.clip, options.texture, report);
  timer.Mark("report");
  return result;
}

Result<MotionClip> TextureHybrid(const MotionDatabase& db, const MotionClip& sketch, const MotionClip& fitted,
                                 const MotionClip& fragments, const FillOptions& options,
                                 const std::vector<SketchPositionKey>& position_keys) {
  RETURN_IF_ERROR(CheckClip(db, sketch, fitted, "fitted clip"));
  RETURN_IF_ERROR(CheckClip(db, sketch, fragments, "fragment clip"));
  ASSIGN_OR_RETURN(const SketchSignals s, MakeSketchSignals(db, sketch));
  const ClipSignals fit = DecomposeClip(db.skeleton(), fitted, db.reference());
  const ClipSignals frag = DecomposeClip(db.skeleton(), fragments, db.reference());
  const int tangent = 3 * db.num_joints();
  Eigen::MatrixXd out = s.values;
  out.leftCols(tangent) = fit.tangent;
  if (out.cols() > tangent) out.rightCols(out.cols() - tangent) = frag.root_features;
  Eigen::MatrixXd source = out;
  source.leftCols(tangent) = frag.tangent;

  const std::vector<std::uint8_t> fixed = FixedJoints(db, s), hold = PositionChains(db, position_keys);
  std::vector<int> keyed_joints, synthesized_joints;
  for (int j = 0; j < db.num_joints(); ++j) {
    if (s.keyed[3 * j]) keyed_joints.push_back(j);
    else if (!fixed[j] && !hold[j]) synthesized_joints.push_back(j);
  }
  std::vector<int> textured_keyed;
  for (int c : Channels(keyed_joints))
    if (!hold[c / 3]) textured_keyed.push_back(c);
  const std::vector<int> synthesized = Channels(synthesized_joints);
  if (options.pca.keyed_base == KeyedBase::kSketch)
    for (int c : textured_keyed) out.col(c) = s.values.col(c);
  if (options.texture) {
    const int bands = TextureBandCount(s.key_spacing, db.rate_hz());
    TextureChannels(out, source, textured_keyed, bands, db.rate_hz(), out);
    if (options.pca.texture_synthesized) TextureChannels(out, source, synthesized, bands, db.rate_hz(), out);
  }
  // Position keys win over rotation keys on their chains: re-pinning a keyed hip there would
  // move the keyed feet (measured: 1.3 cm -> 7.0 cm on the shipped sketch).
  if (options.repin_keys) RepinKeys(s, textured_keyed, out);
  return ComposeFill(db, s, out, sketch, /*textured=*/true);
}

Result<MotionClip> EditHybrid(const MotionDatabase& db, const PcaModel& model, const MotionClip& clip,
                              const PcaMethodOptions& options) {
  MotionClip out = clip;
  if (!options.dials.empty()) {
    PcaEditOptions edit;
    edit.dials = options.dials;
    RETURN_IF_ERROR(edit.Validate(model).WithContext("pca dials"));
    ASSIGN_OR_RETURN(const PcaBinding binding, BindPcaModel(model, db.skeleton()));
    const EncodedClip encoded = EncodeClip(model, binding, db.skeleton(), out);
    ASSIGN_OR_RETURN(const Eigen::MatrixXd poses, EditPoses(model, encoded.poses, edit));
    ASSIGN_OR_RETURN(out, DecodeClip(model, binding, db.skeleton(), encoded, poses, out));
  }
  if (!options.band_gains.empty()) {
    MultiresFilterOptions filter;
    filter.gains.band_gains = options.band_gains;
    filter.reference = &db.reference();
    ASSIGN_OR_RETURN(out, MultiresFilter(db.skeleton(), out, filter));
  }
  return out;
}

Result<FillResult> HybridFill(const MotionDatabase& db, const MotionClip& sketch, const PcaModel* model,
                              const FillOptions& options, const std::vector<SketchPositionKey>& position_keys) {
  FillEngine engine(db);
  engine.SetPcaModel(model);
  FillOptions hybrid = options;
  hybrid.method = FillMethod::kHybrid;
  return engine.Fill(sketch, hybrid, position_keys);
}

}  // namespace mocapfill
