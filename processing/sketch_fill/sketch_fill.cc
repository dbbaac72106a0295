#include "processing/sketch_fill/sketch_fill.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>

#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "processing/core/stopwatch.h"
#include "processing/fill/fill_engine.h"
#include "processing/fill/synthesized_contacts.h"
#include "processing/motion/key_fidelity.h"
#include "processing/motion/resample.h"
#include "processing/retargeting/retarget_scene.h"
#include "processing/sketch_fill/sketch_keys.h"

namespace mocapfill {

namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;

// The database's mean pose as its rest (MeanPoseRest): database clips are captures of a
// standing performer, so this pose stands even where the skeleton's zero pose does not, and
// a capture of the same rig read elsewhere gets much the same rest (ChooseRest's mean pose).
RigRest DatabaseRest(const MotionDatabase& db) {
  RigRest rest = MeanPoseRest(db.skeleton(), db.joint_means(), db.root_joint());
  rest.reason = "the database's mean pose";
  return rest;
}

Result<PreparedRig> PrepareDatabaseRig(const MotionDatabase& db) {
  const RigRest rest = DatabaseRest(db);
  Result<RigMapping> mapping = MapHumanoid(db.skeleton(), rest.WorldPositions(db.skeleton()));
  if (!mapping.ok()) return mapping.status().WithContext("database skeleton");
  ASSIGN_OR_RETURN(HumanoidRig rig, HumanoidRig::Make(db.skeleton(), *mapping, rest));
  return PreparedRig{*mapping, std::move(rig)};
}

// Map overrides may name database joints ("Hips") as well as canonical bones ("hips").
std::map<std::string, std::string> CanonicalOverrides(const std::map<std::string, std::string>& map,
                                                      const Skeleton& database, const RigMapping& db_mapping) {
  std::map<std::string, std::string> out;
  for (const auto& [joint, target] : map) {
    std::string bone = target;
    // A database joint stands for its canonical bone, or for none (joint_Root): unmapped.
    if (!target.empty() && !ParseHumanoidBone(target))
      if (const std::optional<int> d = database.Find(target))
        bone = db_mapping.BoneOfJoint(*d) >= 0 ? HumanoidBoneName(BoneAt(db_mapping.BoneOfJoint(*d))) : "";
    out[joint] = bone;
  }
  return out;
}

Result<PreparedRig> PrepareSketchRig(const Scene& scene, const SketchFillOptions& options, const MotionDatabase& db,
                                     const PreparedRig& db_rig, RigSummary& summary) {
  const Skeleton& s = scene.skeleton;
  const RigOptions rig_options{CanonicalOverrides(options.map, db.skeleton(), db_rig.mapping), options.rest};
  const std::vector<std::uint8_t> none;
  const std::vector<std::uint8_t>& translating = scene.clips.empty() ? none : scene.clips.front().translation_animated;
  summary.same_as_database = SameRig(s, db.skeleton(), translating) && options.rest == RestSource::kAuto;
  PreparedRig prepared;
  if (summary.same_as_database && rig_options.map.empty()) {
    // One rig: the database's own rig geometry, so that retargeting copies local rotations
    // exactly (a rig made anew from the sketch's skeleton aims its hands and head by end
    // sites the database's skeleton may lack: 35 degrees apart on the Bandai-Namco hands).
    prepared = PreparedRig{db_rig.mapping, db_rig.rig.OnSkeleton(s)};
  } else if (summary.same_as_database) {
    // One rig with overrides: share the database's rest so that local rotations carry over.
    RigMapOptions map_options;
    map_options.overrides = rig_options.map;
    ASSIGN_OR_RETURN(RigMapping mapping, MapHumanoid(s, ZeroPose(s).WorldPositions(s), map_options));
    RigRest rest = db_rig.rig.rest();
    rest.local_translations = ZeroPose(s).local_translations;
    rest.reason = "the database's rig and mean pose";
    ASSIGN_OR_RETURN(HumanoidRig rig, HumanoidRig::Make(s, mapping, rest));
    prepared = PreparedRig{std::move(mapping), std::move(rig)};
  } else {
    ASSIGN_OR_RETURN(prepared, PrepareRig(scene, rig_options));
  }
  summary.family = prepared.mapping.family;
  summary.rest = std::string(RestSourceName(prepared.rig.rest().source)) + ": " + prepared.rig.rest().reason;
  for (int b = 0; b < kNumHumanoidBones; ++b) summary.mapped_bones += prepared.mapping.joints[b] >= 0;
  summary.warnings = prepared.mapping.warnings;
  return prepared;
}

// Per sketch joint: 1 when the fill result carries it (a mapped bone, or a torso joint the
// retargeting shares a bone's rotation over); other joints keep the sketch's own values.
std::vector<std::uint8_t> CarriedJoints(const Skeleton& s, const RigMapping& mapping) {
  std::vector<std::uint8_t> carried(s.num_joints(), 0);
  for (int b = 0; b < kNumHumanoidBones; ++b)
    if (mapping.joints[b] >= 0) carried[mapping.joints[b]] = 1;
  // Joints between two mapped torso bones (extra spine or neck joints).
  const int head = mapping.joint(HumanoidBone::kHead) >= 0 ? mapping.joint(HumanoidBone::kHead)
                                                           : mapping.joint(HumanoidBone::kNeck);
  const int hips = mapping.joint(HumanoidBone::kHips);
  for (int j = head; j != kNoParent && j != hips && j >= 0; j = s.parent(j)) carried[j] = 1;
  return carried;
}

// The fill result (on the sketch's rig at the database rate) sampled at the output times;
// joints the fill does not carry are sampled from the sketch itself.
MotionClip SampleOutput(const MotionClip& filled, const MotionClip& sketch, const std::vector<std::uint8_t>& carried,
                        const std::vector<double>& times, bool uniform, double rate_hz) {
  MotionClip out = sketch;
  out.sample_rate_hz = rate_hz;
  out.num_frames = static_cast<int>(times.size());
  out.rotations.assign(times.size() * sketch.num_joints, Quaterniond::Identity());
  out.translations.assign(out.rotations.size(), Vector3d::Zero());
  out.frame_times_s = uniform ? std::vector<double>{} : times;
  for (int j = 0; j < sketch.num_joints; ++j) {
    const MotionClip& from = carried[j] ? filled : sketch;
    out.translation_animated[j] = sketch.translation_animated[j] || filled.translation_animated[j];
    for (int f = 0; f < out.num_frames; ++f) {
      out.rotation(f, j) = SampleRotationAt(from, j, times[f]);
      out.translation(f, j) = SampleTranslationAt(from, j, times[f]);
    }
  }
  return out;
}

std::vector<JointFillInfo> SketchJoints(const Skeleton& s, const RigMapping& sketch_mapping,
                                        const RigMapping& db_mapping, const FillReport& report, const MotionClip& clip,
                                        const std::vector<std::uint8_t>& carried) {
  std::vector<JointFillInfo> joints;
  for (int j = 0; j < s.num_joints(); ++j) {
    JointFillInfo info;
    info.name = s.name(j);
    info.keys = static_cast<int>(RotationKeysOf(clip, j).times_s.size());
    const int bone = sketch_mapping.BoneOfJoint(j);
    const int d = bone >= 0 ? db_mapping.joints[bone] : -1;
    if (d >= 0 && d < static_cast<int>(report.joints.size()) && info.keys > 0)
      info.kind = report.joints[d].kind;
    else
      info.kind = info.keys > 0 ? "keyed" : carried[j] ? "synthesized" : "kept";
    joints.push_back(info);
  }
  return joints;
}

// Where the database does not hold the motion: the time range, how far off, which joints
// are a guess and what they were blended towards.
std::string CoverageWarning(const PoorlyCoveredStretch& stretch, const CoverageReport& coverage, double rate_hz,
                            const std::vector<JointFillInfo>& joints) {
  std::vector<std::string> synthesized;
  for (const JointFillInfo& j : joints)
    if (j.kind == "synthesized") synthesized.push_back(j.name);
  std::string names;
  for (size_t i = 0; i < synthesized.size() && i < 6; ++i) names += (i ? ", " : "") + synthesized[i];
  if (synthesized.size() > 6) names += ", ... (" + std::to_string(synthesized.size()) + " joints)";
  char text[320];
  std::snprintf(text, sizeof text,
                "coverage: %.2f-%.2f s is poorly covered by the database (its nearest match leaves %.0f%% of the "
                "keyed motion unexplained); ",
                stretch.first_frame / rate_hz, stretch.last_frame / rate_hz, 100.0 * stretch.worst_unexplained);
  std::string out = text;
  const bool blended = !coverage.prior.empty() && stretch.max_prior_weight > 0.0;
  if (synthesized.empty()) {
    out += blended ? "the captured detail added to the keyed joints is taken off there"
                   : "the captured detail added to the keyed joints there comes from other motions";
  } else if (!blended) {
    out += "the synthesised joints there are a guess: " + names;
  } else {
    std::snprintf(text, sizeof text, " blended up to %.0f%% towards the %s", 100.0 * stretch.max_prior_weight,
                  coverage.prior == "mean" ? "database mean pose" : "nearest database pose");
    out += names + text;
  }
  return out;
}

// LINEAR interpolation of keyed samples at `time_s` (ends held).
Quaterniond KeyedRotationAt(const RotationKeys& keys, double time_s) {
  const auto& t = keys.times_s;
  if (time_s <= t.front()) return keys.values.front();
  if (time_s >= t.back()) return keys.values.back();
  const size_t k = static_cast<size_t>(std::upper_bound(t.begin(), t.end(), time_s) - t.begin());
  const double u = (time_s - t[k - 1]) / (t[k] - t[k - 1]);
  return keys.values[k - 1].slerp(u, keys.values[k]).normalized();
}

// The limb that carries a position-keyed joint: thigh and shin for a foot, upper arm and
// forearm for a hand, shin and foot for the toes; else the joint's parent and grandparent.
TwoBoneChain ChainOf(const Skeleton& skeleton, const RigMapping& mapping, int joint) {
  using B = HumanoidBone;
  TwoBoneChain chain;
  chain.end = joint;
  const int bone = mapping.BoneOfJoint(joint);
  const std::pair<B, std::array<B, 2>> limbs[] = {
      {B::kLeftFoot, {B::kLeftUpperLeg, B::kLeftLowerLeg}},   {B::kRightFoot, {B::kRightUpperLeg, B::kRightLowerLeg}},
      {B::kLeftHand, {B::kLeftUpperArm, B::kLeftLowerArm}},   {B::kRightHand, {B::kRightUpperArm, B::kRightLowerArm}},
      {B::kLeftToes, {B::kLeftLowerLeg, B::kLeftFoot}},       {B::kRightToes, {B::kRightLowerLeg, B::kRightFoot}},
  };
  for (const auto& [end, pair] : limbs)
    if (bone >= 0 && BoneAt(bone) == end && mapping.has(pair[0]) && mapping.has(pair[1])) {
      chain.upper = mapping.joint(pair[0]);
      chain.lower = mapping.joint(pair[1]);
      return chain;
    }
  chain.lower = skeleton.parent(joint);
  chain.upper = chain.lower == kNoParent ? kNoParent : skeleton.parent(chain.lower);
  return chain;
}

// Translation keys of the listed joints become world-space position targets: where the keys
// put the joint in the sketch, carried to the database's rig like the hips (canonical axes,
// scaled by hip heights). The joints keep their rest offsets (no bone is stretched).
Result<std::vector<SketchPositionKey>> TakePositionKeys(const Skeleton& skeleton, const std::vector<std::string>& names,
                                                        const PreparedRig& sketch_rig, const PreparedRig& db_rig,
                                                        const MotionDatabase& db, MotionClip& clip,
                                                        std::vector<PositionTarget>& targets) {
  std::vector<SketchPositionKey> keys;
  WorldPose pose;
  for (const std::string& name : names) {
    const int j = *skeleton.Find(name);  // CheckTranslationKeys checked the names
    const int bone = sketch_rig.mapping.BoneOfJoint(j);
    if (bone < 0 || db_rig.mapping.joints[bone] < 0)
      return InvalidArgument("position key joint '" + name + "' is not a bone of the canonical humanoid shared with " +
                             "the database's rig");
    const std::string db_joint = db.skeleton().name(db_rig.mapping.joints[bone]);
    const TranslationKeys moves = TranslationKeysOf(clip, j);
    for (size_t k = 0; k < moves.times_s.size(); ++k) {
      const int f = std::clamp(static_cast<int>(std::lround(moves.times_s[k] * clip.sample_rate_hz)), 0,
                               clip.num_frames - 1);
      ComputeWorldPose(skeleton, clip, f, pose);
      targets.push_back({j, moves.times_s[k], pose.positions[j], ChainOf(skeleton, sketch_rig.mapping, j)});
      const Vector3d canonical = sketch_rig.rig.frame().conjugate() * pose.positions[j] / sketch_rig.rig.hip_height_m();
      const int db_frame = static_cast<int>(std::lround(moves.times_s[k] * db.rate_hz()));
      keys.push_back({db_frame, db_joint, db_rig.rig.frame() * canonical * db_rig.rig.hip_height_m()});
    }
    for (int f = 0; f < clip.num_frames; ++f) clip.translation(f, j) = skeleton.joint(j).rest_translation;
    clip.translation_animated[j] = 0;
    clip.keys[j].translation_frames.clear();
    clip.keys[j].translation_times_s.clear();
    clip.keys[j].translation_values.clear();
  }
  return keys;
}

int CountKeys(const MotionClip& clip) {
  int count = 0;
  for (const JointKeys& k : clip.keys) count += !k.empty();
  return count;
}

}  // namespace

std::vector<KeyCheck> CheckKeys(const Skeleton& written_skeleton, const MotionClip& written,
                                const Skeleton& sketch_skeleton, const MotionClip& sketch) {
  std::vector<KeyCheck> checks;
  for (int j = 0; j < sketch_skeleton.num_joints(); ++j) {
    const RotationKeys keys = RotationKeysOf(sketch, j);
    const std::optional<int> w = written_skeleton.Find(sketch_skeleton.name(j));
    if (keys.times_s.empty() || !w) continue;
    const RotationKeys samples = RotationKeysOf(written, *w);
    if (samples.times_s.empty()) continue;
    KeyCheck check;
    check.joint = sketch_skeleton.name(j);
    check.keys = static_cast<int>(keys.times_s.size());
    for (size_t k = 0; k < keys.times_s.size(); ++k) {
      const double e = GeodesicAngle(keys.values[k], KeyedRotationAt(samples, keys.times_s[k])) * kDegPerRad;
      check.mean_deg += e / check.keys;
      check.max_deg = std::max(check.max_deg, e);
    }
    checks.push_back(check);
  }
  return checks;
}

void ApplyKeyChecks(std::vector<KeyCheck> checks, SketchFillResult& result) {
  result.key_checks = std::move(checks);
  result.key_error_mean_deg = result.key_error_max_deg = 0.0;
  int count = 0;
  for (const KeyCheck& k : result.key_checks) {
    result.key_error_max_deg = std::max(result.key_error_max_deg, k.max_deg);
    result.key_error_mean_deg += k.mean_deg * k.keys;
    count += k.keys;
    for (JointFillInfo& j : result.joints)
      if (j.name == k.joint) {
        j.key_error_mean_deg = k.mean_deg;
        j.key_error_max_deg = k.max_deg;
      }
  }
  if (count) result.key_error_mean_deg /= count;
  result.report.key_error_mean_deg = result.key_error_mean_deg;
  result.report.key_error_max_deg = result.key_error_max_deg;
}

Result<SketchFillResult> FillSketch(const Scene& sketch, const MotionDatabase& db, const SketchFillOptions& options,
                                    const PcaModel* model) {
  const auto start = std::chrono::steady_clock::now();
  if (sketch.clips.empty()) return InvalidData("the sketch has no animation");
  MotionClip clip = sketch.clips.front();
  if (clip.num_frames < 1) return InvalidData("the sketch's animation is empty");
  RETURN_IF_ERROR(ApplyKeyOverrides(sketch.skeleton, options.keep, options.synthesize, clip));
  if (CountKeys(clip) == 0) return InvalidData("the sketch has no keyed joint (nothing to fill from)");

  SketchFillResult result;
  ASSIGN_OR_RETURN(const PreparedRig db_rig, PrepareDatabaseRig(db));
  ASSIGN_OR_RETURN(const PreparedRig sketch_rig, PrepareSketchRig(sketch, options, db, db_rig, result.rig));
  const int hips = sketch_rig.mapping.joint(HumanoidBone::kHips);
  RETURN_IF_ERROR(CheckTranslationKeys(sketch.skeleton, clip, hips, options.position_keys));
  std::vector<PositionTarget> targets;
  ASSIGN_OR_RETURN(const std::vector<SketchPositionKey> position_keys,
                   TakePositionKeys(sketch.skeleton, options.position_keys, sketch_rig, db_rig, db, clip, targets));
  for (const std::string& w : result.rig.warnings) result.warnings.push_back(w);
  const double retarget_prepare_s = SecondsSince(start);

  // Onto the database's rig at its rate.
  auto stage = std::chrono::steady_clock::now();
  ResampleOptions at_db;
  at_db.rate_hz = db.rate_hz();
  ASSIGN_OR_RETURN(const MotionClip sketch_at_db, ResampleClip(clip, at_db));
  MotionClip on_db = FromCanonical(db_rig.rig, ToCanonical(sketch_rig.rig, sketch_at_db));
  on_db.name = clip.name;
  const double retarget_in_s = SecondsSince(stage);

  FillEngine engine(db);
  if (model) engine.SetPcaModel(model);
  ASSIGN_OR_RETURN(FillResult filled, engine.Fill(on_db, options.fill, position_keys));

  // Back onto the sketch's rig, at the sketch's own times.
  stage = std::chrono::steady_clock::now();
  const MotionClip back = FromCanonical(sketch_rig.rig, ToCanonical(db_rig.rig, filled.clip), &sketch_at_db);
  result.output_rate_hz = options.output_rate_hz > 0 ? options.output_rate_hz : clip.sample_rate_hz;
  result.database_rate_hz = db.rate_hz();
  const std::vector<double> times = OutputTimes(clip, result.output_rate_hz, result.uniform);
  MotionClip out = SampleOutput(back, clip, CarriedJoints(sketch.skeleton, sketch_rig.mapping), times, result.uniform,
                                result.output_rate_hz);
  PinKeys(clip, hips, out);
  // The fill holds position keys on the database's rig; other proportions move them a little
  // on the sketch's, so the limb is brought onto them here (unless its joints carry rotation
  // keys, which come first).
  std::vector<PositionTarget> reachable;
  std::vector<int> held_by_fill;
  for (const PositionTarget& t : targets) {
    const int chain[3] = {t.chain.upper, t.chain.lower, t.chain.end};
    const bool keyed = std::any_of(std::begin(chain), std::end(chain),
                                   [&](int j) { return j < 0 || !RotationKeysOf(clip, j).times_s.empty(); });
    if (!keyed) {
      reachable.push_back(t);
    } else if (std::find(held_by_fill.begin(), held_by_fill.end(), t.joint) == held_by_fill.end()) {
      held_by_fill.push_back(t.joint);
      result.warnings.push_back("position keys on '" + sketch.skeleton.name(t.joint) +
                                "' are held by the fill alone: the limb above it has rotation keys");
    }
  }
  PinPositionTargets(sketch.skeleton, reachable, out);
  if (options.plant_feet) {
    // A foot keyed by position is where the animator put it at those times, like a rotation key.
    std::vector<LegForPlanting> legs = LegsToPlant(sketch_rig.mapping, clip);
    for (LegForPlanting& leg : legs)
      for (const PositionTarget& t : targets)
        if (t.joint == leg.chain.end || t.joint == leg.toe) leg.pinned_times_s.push_back(t.time_s);
    GiveSynthesizedContacts(filled.report, db.skeleton(), filled.clip, db_rig.mapping, out, legs);
    // Heights scale between the rigs as the hips' translation does.
    const double scale = sketch_rig.rig.hip_height_m() / db_rig.rig.hip_height_m();
    for (LegForPlanting& leg : legs) {
      leg.heel_ground_shift_m *= scale;
      leg.toe_ground_shift_m *= scale;
    }
    result.feet = PlantFeet(sketch.skeleton, legs, options.feet, out);
  }
  out.MakeContinuous();
  out.KeyAllFrames();
  const double retarget_out_s = SecondsSince(stage);

  const TranslationKeys root_keys = TranslationKeysOf(clip, hips);
  for (size_t k = 0; k < root_keys.times_s.size(); ++k)
    result.translation_key_error_max_m = std::max(
        result.translation_key_error_max_m, (SampleTranslationAt(out, hips, root_keys.times_s[k]) - root_keys.values[k]).norm());
  result.max_frame_jump_deg = MaxFrameJumpDeg(out);
  WorldPose pose;
  for (const PositionTarget& target : targets) {
    ComputeWorldPose(sketch.skeleton, out, NearestFrame(out, target.time_s), pose);
    result.position_key_error_max_m =
        std::max(result.position_key_error_max_m, (pose.positions[target.joint] - target.position_m).norm());
  }

  result.joints = SketchJoints(sketch.skeleton, sketch_rig.mapping, db_rig.mapping, filled.report, clip,
                               CarriedJoints(sketch.skeleton, sketch_rig.mapping));
  for (const PoorlyCoveredStretch& stretch : filled.report.coverage.poor)
    result.warnings.push_back(CoverageWarning(stretch, filled.report.coverage, db.rate_hz(), result.joints));
  result.report = std::move(filled.report);
  result.report.stages.insert(result.report.stages.begin(), {"retarget_prepare", retarget_prepare_s});
  result.report.stages.insert(result.report.stages.begin() + 1, {"retarget_in", retarget_in_s});
  result.report.stages.push_back({"retarget_out", retarget_out_s});
  ApplyKeyChecks(CheckKeys(sketch.skeleton, out, sketch.skeleton, clip), result);
  result.scene = sketch;
  result.scene.clips = {std::move(out)};
  result.keyed_sketch = std::move(clip);
  return result;
}

}  // namespace mocapfill
