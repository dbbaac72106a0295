#include "processing/synthesis/fragment_fill_engine.h"

#include <algorithm>
#include <cmath>

#include "processing/core/kinematics.h"
#include "processing/core/smoothstep.h"
#include "processing/filtering/pyramid.h"
#include "processing/synthesis/assembly.h"
#include "processing/synthesis/baselines.h"
#include "processing/synthesis/consensus_weights.h"
#include "processing/synthesis/coverage.h"
#include "processing/synthesis/fill_stages.h"
#include "processing/synthesis/fragment_matching.h"
#include "processing/synthesis/gait_sway.h"
#include "processing/synthesis/ground_contacts.h"
#include "processing/synthesis/hierarchical/hierarchy.h"
#include "processing/synthesis/joining.h"
#include "processing/synthesis/limb_reach.h"
#include "processing/synthesis/local_regression.h"
#include "processing/synthesis/matching_database.h"
#include "processing/synthesis/sketch_signals.h"
#include "processing/synthesis/swing_gain.h"
#include "processing/texturing/repin_keys.h"
#include "processing/texturing/texture_channels.h"

namespace mocapfill {

namespace {

// A still root's travel detail fades back in over this beyond the still keys (a held foot's fade).
constexpr double kStillRootRampS = 0.1;

std::vector<int> RootFeatureChannels(const MotionDatabase& db) {
  std::vector<int> channels;
  if (db.root_joint() >= 0)
    for (int f = 0; f < kNumRootFeatures; ++f) channels.push_back(db.RootFeatureChannel(f));
  return channels;
}

// Everything one fragment-based fill needs, shared by the groups.
struct FragmentContext {
  const MotionDatabase* db;
  const MatchingDatabase* mdb;
  const SketchSignals* sketch;
  const FragmentFillOptions* options;
  std::vector<SketchFragment> fragments;
  Eigen::VectorXf sigma;
  std::vector<int> moving;  // per fragment: 1 where the sketch's root moves (TravellingFragments)
  Eigen::VectorXd sketch_sway;               // LateralSway of the keyed root (gait_sway.h), else empty
  const Eigen::VectorXd* db_sway = nullptr;  // the database's, with sketch_sway
  std::vector<int> swaying;                  // per fragment: 1 where the sway ranks leg candidates
};

// A group's matching drivers: `driven`, or `moving` (when not empty) in the fragments where the
// sketch's root moves.
struct GroupDrivers {
  std::vector<DrivenChannel> driven;
  std::vector<DrivenChannel> moving;
  bool by_sway = false;  // moving fragments rank their candidates by the hips' sway too (gait_sway.h)
};

// Matches, joins and assembles one target set; returns the joined leads and candidates.
struct GroupResult {
  std::vector<std::vector<Candidate>> candidates;
  std::vector<int> leads;
  std::vector<std::vector<double>> weights;  // per fragment, over its BlendSet
};

// A group's candidates should travel as the sketch's root does. A stance foot moves against
// the hips at the root's speed, so legs from takes that stand or walk at another pace slide;
// and a standing sketch's torso and arms are better drawn from takes that stand. Among a
// group's drivers the rest (hips' tilt, torso, legs or arms) outweighed the planar velocity:
// a walk backwards with the upper body keyed took its legs from standing gestures, and the
// blends of standing gestures' arms gave walks and runs a fifth of their weight.
std::vector<DrivenChannel> WeighTravel(const MotionDatabase& db, double factor, std::vector<DrivenChannel> driven) {
  for (DrivenChannel& d : driven)
    if (d.channel == db.RootFeatureChannel(kRootForward) || d.channel == db.RootFeatureChannel(kRootLateral))
      d.weight *= factor;
  return driven;
}

// Per sketch fragment: 1 where the keyed root's planar speed, averaged over the fragment,
// exceeds `speed` (m/s); all 0 when the root's translation is not keyed.
std::vector<int> TravellingFragments(const MotionDatabase& db, const SketchSignals& s,
                                     const std::vector<SketchFragment>& fragments, double speed) {
  std::vector<int> moving(fragments.size(), 0);
  if (!RootFeaturesKeyed(db, s)) return moving;
  const int forward = db.RootFeatureChannel(kRootForward), lateral = db.RootFeatureChannel(kRootLateral);
  for (size_t i = 0; i < fragments.size(); ++i) {
    double sum = 0.0;
    for (int f = fragments[i].first; f <= fragments[i].last; ++f)
      sum += std::hypot(s.values(f, forward), s.values(f, lateral));
    moving[i] = sum / (fragments[i].last - fragments[i].first + 1) > speed;
  }
  return moving;
}

std::vector<DrivenChannel> AllKeyedDrivers(const MotionDatabase& db, const SketchSignals& s,
                                           const FragmentFillOptions& o) {
  std::vector<DrivenChannel> driven;
  for (int c = 0; c < s.num_channels(); ++c)
    if (s.keyed[c]) driven.push_back({c, c >= 3 * db.num_joints() ? o.root_feature_weight : 1.0});
  return driven;
}

// Per fragment, the weight of each candidate of its blend: exp(-d / mean d), turned into the
// local linear regression's equivalent kernel on the candidates' matching features of
// `features` when local_ridge > 0.
std::vector<std::vector<double>> BlendWeights(const FragmentContext& ctx, const Eigen::MatrixXd& match,
                                              const std::vector<DrivenChannel>& features, const GroupResult& r,
                                              int blend) {
  const double ridge = blend > 1 ? ctx.options->local_ridge : 0.0;  // one candidate: nothing to regress
  Eigen::MatrixXf queries;
  if (ridge > 0.0) queries = ScaledSketchFeatures(*ctx.mdb, match, ctx.fragments, features, *ctx.options);
  std::vector<std::vector<double>> weights(ctx.fragments.size());
  for (size_t i = 0; i < ctx.fragments.size(); ++i) {
    const std::vector<Candidate>& cands = r.candidates[i];
    if (cands.empty()) continue;
    const std::vector<int> set = BlendSet(cands, r.leads[i], blend);
    weights[i] = DistanceWeights(cands, set);
    if (ridge <= 0.0 || set.size() < 2) continue;
    std::vector<int> rows;
    for (int k : set) rows.push_back(cands[k].fragment);
    weights[i] = LocalLinearWeights(ScaledDatabaseFeatures(*ctx.mdb, features, rows, ctx.fragments[i], *ctx.options),
                                    queries.row(i).transpose(), weights[i], ridge);
  }
  return weights;
}

// Matches on `drivers`; the local regression of the blend (BlendWeights) runs on `regressors`.
// With `positions` (GroupPositions of the group), the weights then move towards the
// candidates' geometric median posture (consensus_weights.h).
GroupResult SynthesiseGroup(const FragmentContext& ctx, const GroupDrivers& drivers,
                            const std::vector<DrivenChannel>& regressors, const std::vector<int>& targets, int blend,
                            Eigen::MatrixXd& out, StageTimer& timer, const Eigen::MatrixXf* positions = nullptr) {
  const Eigen::MatrixXd match = MatchingSignal(out, ctx.db->rate_hz(), *ctx.options);
  GroupResult r;
  if (drivers.moving.empty())
    r.candidates = MatchFragments(*ctx.mdb, match, ctx.fragments, drivers.driven, *ctx.options);
  else
    r.candidates = MatchFragmentsBySet(*ctx.mdb, match, ctx.fragments, {drivers.driven, drivers.moving}, ctx.moving,
                                       *ctx.options);
  if (drivers.by_sway && ctx.db_sway)
    RankBySway(*ctx.mdb, *ctx.db, ctx.fragments, ctx.swaying, ctx.sketch_sway, *ctx.db_sway,
               ctx.options->leg_sway_weight, r.candidates);
  timer.Mark("match");
  JoinInputs join{ctx.db, ctx.mdb, &r.candidates, targets, ctx.sigma, ctx.options->transition_gamma};
  r.leads = JoinCandidates(ctx.options->join, join);
  timer.Mark("join");
  r.weights = BlendWeights(ctx, match, regressors, r, blend);
  AssemblyInputs assembly{ctx.db, ctx.mdb, &ctx.fragments, &r.candidates, r.leads, blend, targets,
                          ctx.options->crossfade};
  assembly.weights = &r.weights;
  if (positions && ctx.options->consensus_iterations > 0 && blend > 1) {
    r.weights = ConsensusWeights(assembly, *positions, ctx.options->consensus_iterations, ctx.options->consensus_floor_m);
    timer.Mark("consensus");
  }
  AssembleFragments(assembly, out);
  if (ctx.options->crossfade <= 0.0) {
    const int window = static_cast<int>(std::lround(ctx.options->seam_window_s * ctx.db->rate_hz()));
    SmoothSeams(out, targets, ctx.fragments, window);
  }
  timer.Mark("assemble");
  return r;
}

// The blended takes' planar root speed over fragment i's matched frames, as stretched onto the
// fragment, weighted as blended.
double BlendedTravel(const FragmentContext& ctx, const GroupResult& r, size_t i, int blend) {
  const MotionDatabase& db = *ctx.db;
  if (db.root_joint() < 0) return 0.0;
  const int forward = db.RootFeatureChannel(kRootForward), lateral = db.RootFeatureChannel(kRootLateral);
  const std::vector<int> set = BlendSet(r.candidates[i], r.leads[i], blend);
  const std::vector<double>& weights = r.weights[i];  // as blended (SynthesiseGroup sets every fragment's)
  double travel = 0.0;
  for (size_t k = 0; k < set.size(); ++k) {
    const DbFragment& g = ctx.mdb->fragments()[r.candidates[i][set[k]].fragment];
    const int row = db.clip(g.clip).first_frame;
    double speed = 0.0;
    for (int f = g.first; f <= g.last; ++f)
      speed += std::hypot(db.signals()(row + f, forward), db.signals()(row + f, lateral));
    travel += weights[k] * StretchSpeedRatio(g, ctx.fragments[i]) * speed / (g.last - g.first + 1);
  }
  // The regression's weights may extrapolate past the slowest candidates: they stand.
  return std::max(0.0, travel);
}

void ReportGroup(const FragmentContext& ctx, const std::string& name, const GroupResult& r, int blend,
                 FragmentFillReport& report) {
  for (size_t i = 0; i < ctx.fragments.size(); ++i) {
    if (r.candidates[i].empty()) continue;
    const Candidate& c = r.candidates[i][r.leads[i]];
    const DbFragment& g = ctx.mdb->fragments()[c.fragment];
    report.fragments.push_back({name, ctx.fragments[i].first, ctx.fragments[i].last, ctx.db->clip(g.clip).name,
                                g.first, g.last, c.distance, std::min<int>(blend, r.candidates[i].size()),
                                BlendedTravel(ctx, r, i, blend)});
    if (i > 0 && !r.candidates[i - 1].empty() &&
        !Continues(ctx.mdb->fragments()[r.candidates[i - 1][r.leads[i - 1]].fragment], g))
      ++report.seams;
  }
}

// The arms synthesised together among `joints` reach where the blended takes have their hands
// (limb_reach.h).
void ReachLikeTheTakes(const FragmentContext& ctx, const ArmReach* arm_reach, const std::vector<int>& joints,
                       const GroupResult& r, int blend, Eigen::MatrixXd& out) {
  if (!arm_reach) return;
  const std::vector<int> arms = LimbsWithin(arm_reach->arms, joints);
  if (arms.empty()) return;
  std::vector<int> columns;
  for (int i : arms)
    for (int c = 3 * i; c < 3 * i + 3; ++c) columns.push_back(c);
  Eigen::MatrixXd reach = Eigen::MatrixXd::Zero(out.rows(), arm_reach->table.cols());
  const AssemblyInputs assembly{ctx.db, ctx.mdb, &ctx.fragments, &r.candidates, r.leads, blend, columns,
                                ctx.options->crossfade, &arm_reach->table, &r.weights};
  AssembleFragments(assembly, reach);
  ReachLimbs(*ctx.db, *arm_reach, arms, reach, ctx.options->limb_reach, out);
}

// The contacts of the synthesised standing joints among `joints`: the matched takes' own,
// blended with the same candidates, weights and cross-fades as the joints themselves.
void VoteContacts(const FragmentContext& ctx, const DatabaseContacts& contacts, const std::vector<int>& joints,
                  const GroupResult& r, int blend, FragmentFillReport& report) {
  std::vector<int> columns;
  for (size_t k = 0; k < contacts.joints.size(); ++k)
    if (std::find(joints.begin(), joints.end(), contacts.joints[k]) != joints.end())
      columns.push_back(static_cast<int>(k));
  if (columns.empty()) return;
  Eigen::MatrixXd votes = Eigen::MatrixXd::Zero(ctx.sketch->frames, contacts.joints.size());
  const AssemblyInputs assembly{ctx.db, ctx.mdb, &ctx.fragments, &r.candidates, r.leads, blend, columns,
                                ctx.options->crossfade, &contacts.down, &r.weights};
  AssembleFragments(assembly, votes);
  for (SynthesizedContacts& c : VotedContacts(*ctx.db, contacts, columns, votes))
    report.contacts.push_back(std::move(c));
}


// How well the database covers each sketch fragment, on all keyed channels (coverage.h).
CoverageReport MeasureSketchCoverage(const FragmentContext& ctx, CoverageYardstick& yardstick) {
  const MotionDatabase& db = *ctx.db;
  const FragmentFillOptions& options = *ctx.options;
  const std::vector<DrivenChannel> driven = AllKeyedDrivers(db, *ctx.sketch, options);
  std::vector<int> channels;
  for (const DrivenChannel& d : driven) channels.push_back(d.channel);
  if (!yardstick.Serves(channels, options)) {
    yardstick = {ReferenceDistance(*ctx.mdb, driven, options), channels, options.root_feature_weight,
                 options.min_length_ratio, options.max_length_ratio, options.stretched_travel,
                 options.coverage.reference_fragments};
  }
  FragmentFillOptions nearest_only = options;
  nearest_only.candidates = 1;
  const Eigen::MatrixXd match = MatchingSignal(ctx.sketch->values, db.rate_hz(), options);
  const std::vector<std::vector<Candidate>> nearest =
      MatchFragments(*ctx.mdb, match, ctx.fragments, driven, nearest_only);
  const std::vector<float> energies = FragmentEnergies(*ctx.mdb, match, ctx.fragments, driven, options);
  return MeasureCoverage(ctx.fragments, nearest, energies, yardstick.distance, options.coverage);
}

// The keyed root's planar velocities, which the texture gives the lead's detail (empty when
// the sketch does not key the root's translation).
std::vector<int> TravelChannels(const MotionDatabase& db, const SketchSignals& s) {
  if (!RootFeaturesKeyed(db, s)) return {};
  return {db.RootFeatureChannel(kRootForward), db.RootFeatureChannel(kRootLateral)};
}

// Where the keyed root stands still from one key to the next (planar speed below `speed`), its
// travel keeps the keys' low band there (the texture's `bands`), without the lead's detail in
// `out`, which fades back in over `ramp` frames beyond: the lead's hips sway at its own
// amplitude, pinned at every key, and rocked a still sketch's whole body in the keys' rhythm (a
// standing wave: the hips 1 cm off between keys that had them within 0.3 mm).
void KeepStillRootStill(const SketchSignals& s, const std::vector<int>& travel, double speed, int ramp, int bands,
                        double rate, Eigen::MatrixXd& out) {
  if (speed <= 0.0 || travel.size() != 2) return;
  const std::vector<int>& keys = s.key_frames[travel[0]];
  std::vector<int> still_frames;
  for (size_t k = 0; k + 1 < keys.size(); ++k) {
    double fastest = 0.0;
    for (int f = keys[k]; f <= keys[k + 1]; ++f)
      fastest = std::max(fastest, std::hypot(s.values(f, travel[0]), s.values(f, travel[1])));
    if (fastest < speed)
      for (int f = keys[k]; f <= keys[k + 1]; ++f) still_frames.push_back(f);
  }
  if (still_frames.empty()) return;
  Eigen::MatrixXd low = out;
  LowBandChannels(s.values, travel, bands, rate, low);
  std::vector<double> detail(out.rows(), 1.0);
  for (int f : still_frames)
    for (int d = -ramp; d <= ramp; ++d)
      if (f + d >= 0 && f + d < out.rows())
        detail[f + d] = std::min(detail[f + d], Smoothstep(double(std::abs(d)) / (ramp + 1)));
  for (int f = 0; f < out.rows(); ++f)
    for (int c : travel) out(f, c) = low(f, c) + detail[f] * (out(f, c) - low(f, c));
}

// Blends poorly covered stretches towards the prior: synthesised channels towards the mean
// pose or the nearest database pose, keyed ones towards the sketch (their texture fades;
// keys stay exact, the sketch holds them), each with its own weight. The keyed travel fades
// to the low band of the keys' velocities, as the texture has it: their own (the interval
// means, a path linear between keys) kinked at every key and jolted the whole body there.
void BlendPoorCoverage(const MotionDatabase& db, const SketchSignals& s, const FragmentFillOptions& options,
                       const CoverageReport& coverage, Eigen::MatrixXd& out) {
  const Eigen::VectorXd prior_weight = WeightPerFrame(coverage, &FragmentCoverage::prior_weight, s.frames);
  const Eigen::VectorXd texture_weight = WeightPerFrame(coverage, &FragmentCoverage::texture_weight, s.frames);
  if (!(prior_weight.maxCoeff() > 0.0) && !(texture_weight.maxCoeff() > 0.0)) return;
  Eigen::MatrixXd prior = s.values;
  if (options.coverage.prior == CoveragePrior::kMean) {
    FillMean(s, prior);
  } else {
    FillNearest(db, s, options, prior);
  }
  LowBandChannels(s.values, TravelChannels(db, s), TextureBandCount(s.key_spacing, db.rate_hz()), db.rate_hz(), prior);
  std::vector<int> synthesized, keyed;
  for (int c = 0; c < s.num_channels(); ++c) (s.keyed[c] ? keyed : synthesized).push_back(c);
  BlendTowards(prior, prior_weight, synthesized, out);
  BlendTowards(prior, prior_weight.cwiseMax(texture_weight), keyed, out);
}

// Adds `gain` times the `bands` finest pyramid bands of `targets` as the group's lead candidates
// alone give them (AssembleFragments with a blend of 1; frames without candidates keep the
// blend's values, which have no detail to give) to `detail`: DropFinestBands takes those bands
// off the blend, and a share of one take's come back.
void AddLeadDetail(const FragmentContext& ctx, const GroupResult& r, const std::vector<int>& targets, int bands,
                   double gain, const Eigen::MatrixXd& blended, Eigen::MatrixXd& detail) {
  if (gain <= 0.0 || bands <= 0 || blended.rows() < 2) return;
  AssemblyInputs lead{ctx.db, ctx.mdb, &ctx.fragments, &r.candidates, r.leads, 1, targets, ctx.options->crossfade};
  Eigen::MatrixXd alone = blended;
  AssembleFragments(lead, alone);
  Eigen::MatrixXd block(alone.rows(), targets.size());
  for (size_t i = 0; i < targets.size(); ++i) block.col(i) = alone.col(targets[i]);
  Eigen::MatrixXd smooth = block;
  for (int level = 0; level < bands; ++level) smooth = SmoothLevel(smooth, level, PyramidBoundary::kClamp);
  for (size_t i = 0; i < targets.size(); ++i) detail.col(targets[i]) += gain * (block.col(i) - smooth.col(i));
}

// Leaves the `bands` finest pyramid bands out of the listed channels of `out` (replaces them by
// G_bands): above 7.5 Hz at 30 Hz the blend of other takes carries the jolts of its own
// candidates and cross-fades, not detail of the motion being filled.
void DropFinestBands(const std::vector<int>& channels, int bands, Eigen::MatrixXd& out) {
  if (bands <= 0 || channels.empty() || out.rows() < 2) return;
  Eigen::MatrixXd smooth(out.rows(), channels.size());
  for (size_t i = 0; i < channels.size(); ++i) smooth.col(i) = out.col(channels[i]);
  for (int level = 0; level < bands; ++level) smooth = SmoothLevel(smooth, level, PyramidBoundary::kClamp);
  for (size_t i = 0; i < channels.size(); ++i) out.col(channels[i]) = smooth.col(i);
}

// Chains hanging well below the motion root in the database's mean pose (the legs). Their
// steps must follow the sketch's own progression, and averaging many takes' strides of
// slightly different phase blurs them, so they blend fewer candidates (leg_blend).
std::vector<std::uint8_t> HangingJoints(const MotionDatabase& db) {
  MotionClip mean = MotionClip::RestPose(db.skeleton(), 1, db.rate_hz());
  for (int j = 0; j < db.num_joints(); ++j) mean.rotation(0, j) = db.joint_means()[j];
  const std::vector<Eigen::Vector3d> p = ComputeWorldPositions(db.skeleton(), mean);
  const double root = p[db.root_joint()].y();
  double lowest = root;
  for (const Eigen::Vector3d& q : p) lowest = std::min(lowest, q.y());
  std::vector<std::uint8_t> hanging(db.num_joints(), 0);
  for (int j = 0; j < db.num_joints(); ++j) hanging[j] = p[j].y() < root - 0.5 * (root - lowest);
  return hanging;
}

// The motion root and the leg chains: every joint that is hanging or carries one (the thighs).
std::vector<std::uint8_t> LowerBody(const MotionDatabase& db, const std::vector<std::uint8_t>& hanging) {
  std::vector<std::uint8_t> lower(hanging);
  for (int j = 0; j < db.num_joints(); ++j)
    if (hanging[j])
      for (int p = db.skeleton().parent(j); p != kNoParent && !lower[p]; p = db.skeleton().parent(p)) lower[p] = 1;
  if (db.root_joint() >= 0) lower[db.root_joint()] = 1;
  return lower;
}

Status RunFragmentMethod(const MotionDatabase& db, std::unique_ptr<MatchingDatabase>& cache,
                         CoverageYardstick& yardstick, std::unique_ptr<DatabaseContacts>& contacts,
                         std::unique_ptr<ArmReach>& arm_reach, GroupPositionCache& group_positions,
                         Eigen::VectorXd& db_sway, const SketchSignals& s,
                         const FragmentFillOptions& requested, Eigen::MatrixXd& out, FragmentFillReport& report,
                         StageTimer& timer) {
  const std::vector<std::uint8_t> hanging = HangingJoints(db);
  // Keyed legs carry the sketch's gait: its pace (their takes are matched at captured speed),
  // moving_travel_weight and, textured, the contacts of their texture's take (VoteContacts below).
  std::vector<int> keyed_legs;
  for (int j = 0; j < db.num_joints(); ++j)
    if (s.keyed[3 * j] && hanging[j]) keyed_legs.push_back(j);
  const bool legs_keyed = !keyed_legs.empty();
  FragmentFillOptions options = requested;
  options.stretched_travel = requested.stretched_travel && !legs_keyed;
  const double rate = db.rate_hz();
  const int band = BandForFrequency(options.fragment_band_hz, rate, 16);
  const int master = ChooseMasterChannel(s, band, rate);
  FragmentContext ctx{&db, nullptr, &s, &options, {}, ChannelSigma(db), {}, {}, nullptr, {}};
  ASSIGN_OR_RETURN(ctx.fragments, FragmentSketch(s, master, band, rate));
  ctx.moving = TravellingFragments(db, s, ctx.fragments, options.moving_speed_m_per_s);
  report.master_channel = db.ChannelName(master);
  report.fragment_band = band;
  report.sketch_fragments = static_cast<int>(ctx.fragments.size());
  timer.Mark("fragment");
  if (!cache || !cache->Serves(s, master, band, options)) {
    ASSIGN_OR_RETURN(MatchingDatabase built, MatchingDatabase::Build(db, s, master, band, options));
    cache = std::make_unique<MatchingDatabase>(std::move(built));
    yardstick = {};
  }
  ctx.mdb = cache.get();
  timer.Mark("filter_db");
  report.coverage = MeasureSketchCoverage(ctx, yardstick);
  timer.Mark("coverage");

  const std::vector<std::uint8_t> fixed = FixedJoints(db, s);
  std::vector<int> root_targets;
  if (!RootFeaturesKeyed(db, s)) root_targets = RootFeatureChannels(db);
  // Every channel the fill synthesises: the joints no key fixes, and the root features when
  // the root is not keyed.
  std::vector<int> joints;
  for (int j = 0; j < db.num_joints(); ++j)
    if (!fixed[j]) joints.push_back(j);
  const std::vector<int> joint_channels = JointChannels(joints);
  std::vector<int> synthesized = joint_channels;
  synthesized.insert(synthesized.end(), root_targets.begin(), root_targets.end());
  const bool legs_synthesized = std::any_of(joints.begin(), joints.end(), [&](int j) { return hanging[j] != 0; });
  if (!contacts && ((options.texture && legs_keyed) || legs_synthesized)) {
    ASSIGN_OR_RETURN(DatabaseContacts found, FindDatabaseContacts(db, hanging));
    contacts = std::make_unique<DatabaseContacts>(std::move(found));
    timer.Mark("db_contacts");
  }
  if (options.limb_reach > 0.0 && !arm_reach) {
    arm_reach = std::make_unique<ArmReach>(PrepareArmReach(db));
    timer.Mark("arm_reach");
  }
  const ArmReach* reaching = options.limb_reach > 0.0 ? arm_reach.get() : nullptr;
  // Synthesised legs under keyed hips step on the foot the hips sway over (gait_sway.h).
  if (options.leg_sway_weight > 0.0 && legs_synthesized && RootFeaturesKeyed(db, s)) {
    const int half_window = static_cast<int>(std::lround(kSwayHalfWindowS * rate));
    if (db_sway.size() != db.num_frames()) {
      db_sway = DatabaseSway(db, half_window);
      timer.Mark("db_sway");
    }
    Eigen::MatrixXd features(s.frames, kNumRootFeatures);
    for (int k = 0; k < kNumRootFeatures; ++k) features.col(k) = s.values.col(db.RootFeatureChannel(k));
    ctx.sketch_sway = LateralSway(features, rate, half_window);
    ctx.swaying = TravellingFragments(db, s, ctx.fragments, options.sway_speed_m_per_s);
    ctx.db_sway = &db_sway;
  }
  const std::vector<DrivenChannel> all_keyed = AllKeyedDrivers(db, s, options);
  Eigen::MatrixXd lead_detail = Eigen::MatrixXd::Zero(out.rows(), out.cols());
  if (options.method == FillMethod::kFragment) {
    if (!synthesized.empty()) {
      const GroupResult r = SynthesiseGroup(ctx, {all_keyed, {}}, all_keyed, synthesized, options.blend, out, timer);
      ReachLikeTheTakes(ctx, reaching, joints, r, options.blend, out);
      ReportGroup(ctx, "missing joints", r, options.blend, report);
      if (contacts) VoteContacts(ctx, *contacts, joints, r, options.blend, report);
    }
  } else {
    std::vector<std::uint8_t> available = fixed, keyed(db.num_joints(), 0);
    for (int j = 0; j < db.num_joints(); ++j) keyed[j] = s.keyed[3 * j];
    bool first = true;
    for (const JointGroup& group : PlanGroups(db.skeleton(), fixed)) {
      const bool leg = hanging[group.joints.back()] && options.leg_drivers > 0;
      std::vector<DrivenChannel> driven = ChooseDrivers(
          db, group, available, keyed, RootFeaturesKeyed(db, s), leg ? options.leg_drivers : options.max_drivers,
          options.synthesized_driver_weight, options.root_feature_weight, options.root_drives || leg);
      if (driven.empty()) driven = all_keyed;
      GroupDrivers matched_on{WeighTravel(db, options.travel_weight, driven), {}};
      if (!hanging[group.joints.back()] && legs_keyed && options.moving_travel_weight != options.travel_weight)
        matched_on.moving = WeighTravel(db, options.moving_travel_weight, driven);
      matched_on.by_sway = hanging[group.joints.back()] != 0;
      driven = matched_on.driven;
      std::vector<int> targets = JointChannels(group.joints);
      if (first) targets.insert(targets.end(), root_targets.begin(), root_targets.end());
      first = false;
      const int blend = hanging[group.joints.back()] ? std::min(options.blend, options.leg_blend) : options.blend;
      // A group's candidates are matched on its few most correlated drivers, but what varies
      // among them is regressed on every keyed channel: 160 candidates support the wider fit,
      // the 32 of a leg chain do not (docs/fill.md, step 6).
      // The legs' steps follow the sketch's own progression, not a consensus of the takes'.
      const Eigen::MatrixXf* positions = nullptr;
      if (!hanging[group.joints.back()] && options.consensus_iterations > 0) {
        auto cached = group_positions.find(group.joints);
        if (cached == group_positions.end()) {
          cached = group_positions.emplace(group.joints, GroupPositions(db, group.joints)).first;
          timer.Mark("group_positions");
        }
        positions = &cached->second;
      }
      const GroupResult r = SynthesiseGroup(ctx, matched_on, hanging[group.joints.back()] ? driven : all_keyed, targets,
                                            blend, out, timer, positions);
      ReachLikeTheTakes(ctx, reaching, group.joints, r, blend, out);
      if (!hanging[group.joints.back()] && blend > 1)
        AddLeadDetail(ctx, r, targets, options.synthesized_finest_band, options.lead_detail, out, lead_detail);
      ReportGroup(ctx, group.name, r, blend, report);
      if (contacts) VoteContacts(ctx, *contacts, group.joints, r, blend, report);
      std::string drivers;
      for (size_t i = 0; i < driven.size(); i += 3) {
        const bool features = driven[i].channel >= 3 * db.num_joints();
        drivers += (i ? "," : "") + (features ? std::string("root features") : db.skeleton().name(driven[i].channel / 3));
        if (features) break;  // the root features close the list
      }
      report.group_order.push_back(group.name + " <- " + drivers);
      for (int j : group.joints) available[j] = 1;
    }
  }
  DropFinestBands(synthesized, options.synthesized_finest_band, out);
  // A single take (blend 1) has nothing cancelled to give back.
  if (options.method == FillMethod::kHierarchical && options.blend > 1)
    ScaleSwing(joint_channels, options.swing_gain, static_cast<int>(std::lround(kSwingHalfWindowS * rate)), out);
  out += lead_detail;
  if (options.texture) {
    std::vector<int> keyed_channels;
    for (int c = 0; c < 3 * db.num_joints(); ++c)
      if (s.keyed[c] && !fixed.empty()) keyed_channels.push_back(c);
    // A keyed root's travel is textured like a keyed joint (its keys' low band plus the lead's
    // detail): the sketch's path, linear between keys, kinks at every key and jolts the whole
    // body there. The planar velocities are textured here and the path they integrate to is
    // pinned onto the keys (ComposeFill). The height is not textured (ComposeFill runs a smooth
    // curve through its keys): a captured bob the legs' planted feet do not follow made the
    // knees snap into the keys. The yaw rate is left as keyed: the heading it integrates to
    // must meet the root's rotation keys.
    const std::vector<int> root_channels = TravelChannels(db, s);
    Eigen::MatrixXd source = out;
    const GroupResult r = SynthesiseGroup(ctx, {all_keyed, {}}, all_keyed, keyed_channels, 1, source, timer);
    // The keyed feet stand where the take lending them its detail stood: keys sparser than a
    // step (every 8 or 16 frames) miss much of each contact, and the feet slid there (legs16:
    // 18 cm/s during the capture's contacts on the tuning half).
    if (!keyed_legs.empty() && contacts) VoteContacts(ctx, *contacts, keyed_legs, r, 1, report);
    if (!root_channels.empty()) {
      // From the same takes as the joints' texture, so that hips and legs move together.
      AssemblyInputs lead{&db, ctx.mdb, &ctx.fragments, &r.candidates, r.leads, 1, root_channels, options.crossfade};
      lead.weights = &r.weights;
      AssembleFragments(lead, source);
    }
    std::vector<int> textured = keyed_channels;
    textured.insert(textured.end(), root_channels.begin(), root_channels.end());
    const int bands = TextureBandCount(s.key_spacing, rate);
    // Only the upper body's detail follows the sketch's liveliness: the legs' carries the steps
    // that keys every 8 or 16 frames alias, and the hips' is the only jerk a sketch of the root
    // alone gets, which was already smoother than capture (docs/fill.md, step 8).
    ActivityMatch activity;
    Eigen::MatrixXd source_as_keyed;
    if (options.texture_activity_window_s > 0.0) {
      const std::vector<std::uint8_t> lower = LowerBody(db, hanging);
      for (int c : keyed_channels)
        if (!lower[c / 3]) activity.channels.push_back(c);
      if (!activity.channels.empty()) {
        source_as_keyed = source;
        for (int c : activity.channels) LerpBetweenKeys(source_as_keyed.middleCols(c, 1), s.key_frames[c]);
        activity.source_as_keyed = &source_as_keyed;
        activity.window_s = options.texture_activity_window_s;
      }
    }
    TextureChannels(s.values, source, textured, bands, rate, out, options.texture_finest_band, activity);
    KeepStillRootStill(s, root_channels, options.still_root_m_per_s,
                       static_cast<int>(std::lround(kStillRootRampS * rate)), bands, rate, out);
    if (options.repin_keys) RepinKeys(s.values, s.key_frames, keyed_channels, out);
    timer.Mark("texture");
  }
  if (report.coverage.measured && options.coverage.blend) {
    BlendPoorCoverage(db, s, options, report.coverage, out);
    timer.Mark("coverage_blend");
  }
  return OkStatus();
}

}  // namespace

FragmentFillEngine::FragmentFillEngine(const MotionDatabase& db) : db_(db) {}
FragmentFillEngine::~FragmentFillEngine() = default;

Result<MotionClip> FragmentFillEngine::Fill(const MotionClip& sketch, const FragmentFillOptions& options,
                                            FragmentFillReport& report) {
  RETURN_IF_ERROR(options.Validate());
  RETURN_IF_ERROR(CheckFillSketch(db_, sketch));
  if (options.method == FillMethod::kPca || options.method == FillMethod::kHybrid)
    return InvalidArgument(std::string("the ") + FillMethodName(options.method) +
                           " method needs a PCA model: FillEngine (processing/fill) runs it");
  report = FragmentFillReport{};
  report.method = FillMethodName(options.method);
  report.join = JoinCriterionName(options.join);
  report.frames = sketch.num_frames;
  report.rate_hz = db_.rate_hz();
  StageTimer timer(report);
  ASSIGN_OR_RETURN(const SketchSignals s, MakeSketchSignals(db_, sketch));
  report.key_spacing_frames = s.key_spacing;
  Eigen::MatrixXd out = s.values;
  timer.Mark("prepare");
  const bool fragment_based = options.method == FillMethod::kFragment || options.method == FillMethod::kHierarchical;
  if (options.method == FillMethod::kMean) {
    FillMean(s, out);
  } else if (options.method == FillMethod::kNearest) {
    FillNearest(db_, s, options, out);
  } else {
    RETURN_IF_ERROR(RunFragmentMethod(db_, cache_, yardstick_, contacts_, arm_reach_, group_positions_, db_sway_, s,
                                      options, out, report, timer));
  }
  timer.Mark(options.method == FillMethod::kMean ? "mean_pose" : fragment_based ? "assemble" : "match");
  const bool textured = fragment_based && options.texture;
  ASSIGN_OR_RETURN(MotionClip clip, ComposeFill(db_, s, out, sketch, textured));
  ReportJoints(db_, s, sketch, clip, textured, report);
  timer.Mark("compose");
  return clip;
}

}  // namespace mocapfill
