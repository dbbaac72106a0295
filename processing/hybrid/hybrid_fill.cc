#include "processing/hybrid/hybrid_fill.h"

#include <cstdint>
#include <optional>
#include <string>

#include "processing/filtering/motion_filter.h"
#include "processing/motion/tangent_space.h"
#include "processing/pca/pca_clip.h"
#include "processing/pca/pca_edit.h"
#include "processing/synthesis/fill_stages.h"
#include "processing/synthesis/sketch_signals.h"
#include "processing/texturing/repin_keys.h"
#include "processing/texturing/texture_channels.h"

namespace mocapfill {

namespace {

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
void TakeFragmentReport(const FragmentFillReport& from, FragmentFillReport& to) {
  to.master_channel = from.master_channel;
  to.fragment_band = from.fragment_band;
  to.sketch_fragments = from.sketch_fragments;
  to.seams = from.seams;
  to.fragments = from.fragments;
  to.group_order = from.group_order;
  to.contacts = from.contacts;  // the feet stand where the fragments' takes stood
  for (const StageTime& t : from.stages) to.stages.push_back({"fragments." + t.stage, t.seconds});
}

}  // namespace

Result<HybridResult> HybridFill(FragmentFillEngine& fragments, const PcaModel& model, const MotionClip& sketch,
                                const FragmentFillOptions& options, const PcaMethodOptions& pca,
                                const std::vector<SketchPositionKey>& position_keys, FragmentFillReport& report) {
  RETURN_IF_ERROR(pca.Validate().WithContext("pca"));
  const MotionDatabase& db = fragments.db();
  report.method = FillMethodName(FillMethod::kHybrid);
  report.join = JoinCriterionName(options.join);
  report.frames = sketch.num_frames;
  report.rate_hz = db.rate_hz();
  StageTimer timer(report);
  // 1. Hierarchical fragments (their own texture adds the lead candidates' high bands to the
  // keyed joints, which stage 3 passes on).
  FragmentFillOptions fragment_options = options;
  fragment_options.method = FillMethod::kHierarchical;
  FragmentFillReport fragment_report;
  ASSIGN_OR_RETURN(const MotionClip fragment_clip, fragments.Fill(sketch, fragment_options, fragment_report));
  TakeFragmentReport(fragment_report, report);
  report.key_spacing_frames = fragment_report.key_spacing_frames;
  timer.Mark("fragments");
  // 2. The Ceres fit to the keys, guided towards the fragments on the unkeyed joints.
  ASSIGN_OR_RETURN(const PcaSketchFit fitted,
                   FitSketchToKeys(model, db.skeleton(), sketch, position_keys, &fragment_clip, pca.fit));
  HybridResult result;
  result.solver = fitted.fit.report;
  timer.Mark("pca_fit");
  // 3. Texture and key re-pinning.
  ASSIGN_OR_RETURN(const MotionClip textured,
                   TextureHybrid(db, sketch, fitted.clip, fragment_clip, options, pca, position_keys));
  timer.Mark("hybrid_texture");
  // 4. Optional edits.
  ASSIGN_OR_RETURN(result.clip, EditHybrid(db, model, textured, pca));
  timer.Mark("edit");
  ASSIGN_OR_RETURN(const SketchSignals s, MakeSketchSignals(db, sketch));
  ReportJoints(db, s, sketch, result.clip, options.texture, report);
  timer.Mark("report");
  return result;
}

Result<MotionClip> TextureHybrid(const MotionDatabase& db, const MotionClip& sketch, const MotionClip& fitted,
                                 const MotionClip& fragments, const FragmentFillOptions& options,
                                 const PcaMethodOptions& pca, const std::vector<SketchPositionKey>& position_keys) {
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
  if (pca.keyed_base == KeyedBase::kSketch)
    for (int c : textured_keyed) out.col(c) = s.values.col(c);
  if (options.texture) {
    const int bands = TextureBandCount(s.key_spacing, db.rate_hz());
    TextureChannels(out, source, textured_keyed, bands, db.rate_hz(), out);
    if (pca.texture_synthesized) TextureChannels(out, source, synthesized, bands, db.rate_hz(), out);
  }
  // Position keys win over rotation keys on their chains: re-pinning a keyed hip there would
  // move the keyed feet by centimetres.
  if (options.repin_keys) RepinKeys(s.values, s.key_frames, textured_keyed, out);
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

}  // namespace mocapfill
