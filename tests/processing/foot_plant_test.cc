// Planted feet (processing/motion/foot_plant.h) and the contacts they hold
// (processing/motion/foot_contacts.h), on captured walks and the shipped sketch.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "formats/motion_io.h"
#include "processing/core/kinematics.h"
#include "processing/core/rotation.h"
#include "processing/evaluation/metrics.h"
#include "processing/evaluation/scenarios.h"
#include "processing/evaluation/sketch_maker.h"
#include "processing/database/stored_clips.h"
#include "processing/fill/synthesized_contacts.h"
#include "processing/motion/foot_contacts.h"
#include "processing/motion/foot_plant.h"
#include "processing/motion/key_fidelity.h"
#include "processing/motion/key_stances.h"
#include "processing/retargeting/rig_mapping.h"
#include "processing/sketch_fill/sketch_fill.h"
#include "processing/synthesis/ground_contacts.h"
#include "tests/support/default_db.h"
#include "tests/support/test_paths.h"

namespace mocapfill {
namespace {

constexpr double kPlantedKeysToleranceDeg = 0.01;

std::vector<Eigen::Vector3d> TrackOf(const Skeleton& skeleton, const MotionClip& clip, int joint) {
  std::vector<Eigen::Vector3d> track;
  WorldPose pose;
  for (int f = 0; f < clip.num_frames; ++f) {
    ComputeWorldPose(skeleton, clip, f, pose);
    track.push_back(pose.positions[joint]);
  }
  return track;
}

std::vector<double> TimesOf(const MotionClip& clip) {
  std::vector<double> times;
  for (int f = 0; f < clip.num_frames; ++f) times.push_back(clip.time_s(f));
  return times;
}

double Lowest(const std::vector<Eigen::Vector3d>& track) {
  double lowest = INFINITY;
  for (const Eigen::Vector3d& p : track) lowest = std::min(lowest, p.y());
  return lowest;
}

const char* const kFeet[] = {"Foot_L", "Toes_L", "Foot_R", "Toes_R"};

// On a captured walk, every frame where a foot joint stands still (the LaFAN1 rule: under
// 4.24 cm/s) is found by the detector, which looks at height and a looser speed only.
TEST(FootContacts, CapturedWalkStillFramesAreContacts) {
  Result<Scene> walk = ImportFile(testing::FixturePath("default_db/dataset-1_walk_normal_001.bvh"));
  ASSERT_TRUE(walk.ok()) << walk.status().message();
  const MotionClip& clip = walk->clips[0];
  int still = 0, found = 0, detected = 0;
  for (const char* name : kFeet) {
    const int joint = *walk->skeleton.Find(name);
    const std::vector<Eigen::Vector3d> track = TrackOf(walk->skeleton, clip, joint);
    const std::vector<bool> contact = DetectContacts(track, TimesOf(clip), Lowest(track), {});
    for (int f = 0; f + 1 < clip.num_frames; ++f) {
      const bool is_still = (track[f + 1] - track[f]).norm() / (clip.time_s(f + 1) - clip.time_s(f)) < 0.0424;
      still += is_still;
      found += is_still && contact[f];
      detected += contact[f];
    }
  }
  std::printf("captured walk: %d still foot-frames, %d of them detected; %d detected in all\n", still, found, detected);
  ASSERT_GT(still, 100);
  EXPECT_GE(found, 0.95 * still);
  EXPECT_LT(detected, 0.7 * 4 * clip.num_frames);  // swing frames are not contacts
}

// Keys every 16 frames on a captured walk (shipped fixture), with the capture's own hips: a
// foot on the ground at a key stands there while the hips pass over it, from a fifth of its
// reach ahead of them to a quarter behind. Every frame the rule has standing is one the
// detector has on the ground, two in three are still in the capture (under 4.24 cm/s; the
// others roll onto the toe), and they are two in three of the capture's still frames, where
// the keys alone are one in nine (measured 217 frames, 146 still; 217 still, 25 at keys).
TEST(KeyStances, CapturedWalkStandsWhereItsKeysPutIt) {
  Result<Scene> walk = ImportFile(testing::FixturePath("default_db/dataset-1_walk_normal_001.bvh"));
  ASSERT_TRUE(walk.ok()) << walk.status().message();
  const MotionClip& clip = walk->clips[0];
  const std::vector<double> times = TimesOf(clip);
  const std::vector<Eigen::Vector3d> hips = TrackOf(walk->skeleton, clip, *walk->skeleton.Find("Hips"));
  std::vector<bool> pinned(clip.num_frames, false);
  for (int f = 0; f < clip.num_frames; f += 16) pinned[f] = true;
  int marked = 0, marked_still = 0, marked_down = 0, still = 0, keys_still = 0;
  for (const char* name : kFeet) {
    const std::vector<Eigen::Vector3d> track = TrackOf(walk->skeleton, clip, *walk->skeleton.Find(name));
    const std::vector<bool> down = DetectContacts(track, times, Lowest(track), {});
    const std::vector<bool> stance = StancesAroundKeys(track, hips, times, pinned, down, Lowest(track), {});
    for (int f = 0; f + 1 < clip.num_frames; ++f) {
      const bool is_still = (track[f + 1] - track[f]).norm() / (times[f + 1] - times[f]) < 0.0424;
      still += is_still;
      marked += stance[f];
      marked_still += stance[f] && is_still;
      marked_down += stance[f] && down[f];
      keys_still += pinned[f] && is_still;
    }
  }
  std::printf("captured walk, keys every 16 frames: %d foot-frames stand at a key, %d of them still; %d still "
              "foot-frames, %d of them keys; %d on the ground\n", marked, marked_still, still, keys_still, marked_down);
  ASSERT_GT(still, 100);
  EXPECT_GE(marked_down, 0.95 * marked);
  EXPECT_GE(marked_still, 0.6 * marked);
  EXPECT_GT(marked_still, 4 * keys_still);
}

// A foot stands at the median height of its contacts; one that never stands, at its lowest.
TEST(FootContacts, StandingHeightIsTheContactsMedianElseTheLowest) {
  Result<Scene> walk = ImportFile(testing::FixturePath("default_db/dataset-1_walk_normal_001.bvh"));
  ASSERT_TRUE(walk.ok()) << walk.status().message();
  const std::vector<Eigen::Vector3d> track = TrackOf(walk->skeleton, walk->clips[0], *walk->skeleton.Find("Foot_L"));
  const std::vector<bool> contact = DetectContacts(track, TimesOf(walk->clips[0]), Lowest(track), {});
  const double standing = StandingOrLowestHeight(track, contact);
  EXPECT_EQ(standing, StandingHeight(track, contact));
  EXPECT_GT(standing, Lowest(track));  // the heel rolls below its standing height
  EXPECT_LT(standing, Lowest(track) + 0.03);
  EXPECT_EQ(StandingOrLowestHeight(track, std::vector<bool>(track.size(), false)), Lowest(track));
  EXPECT_EQ(StandingOrLowestHeight({}, {}), -INFINITY);
}

// The contacts the planter finds on a fill (the legs keyed every 8 frames, free feet) are those
// the same detector finds on the capture the sketch was made from, on at least 90 % of frames,
// with a database that covers walking (the corpus without the sketch's style, as in
// leave-one-style-out; the 3-style default database textures these legs so freely that
// their feet leave the ground between keys: 57 % there).
TEST(FootPlant, FilledContactsMatchTheCapture) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<Scene> truth = ImportFile(testing::DataPath("bandai-namco-1/data/dataset-1_walk_proud_002.bvh"));
  Result<Scene> sketch = ImportFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  ASSERT_TRUE(truth.ok() && sketch.ok());
  SketchFillOptions options;
  options.plant_feet = false;
  Result<SketchFillResult> filled = FillSketch(*sketch, testing::BandaiDbWithout("proud"), options);
  ASSERT_TRUE(filled.ok()) << filled.status().message();
  const MotionClip& out = filled->scene.clips[0];
  const MotionClip& capture = truth->clips[0];
  const int frames = std::min(out.num_frames, capture.num_frames);
  ASSERT_GE(frames, 300);
  int agree = 0, total = 0;
  for (const char* name : kFeet) {
    const int in_out = *filled->scene.skeleton.Find(name), in_capture = *truth->skeleton.Find(name);
    const std::vector<Eigen::Vector3d> a = TrackOf(filled->scene.skeleton, out, in_out);
    const std::vector<Eigen::Vector3d> b = TrackOf(truth->skeleton, capture, in_capture);
    const std::vector<bool> ca = DetectContacts(a, TimesOf(out), Lowest(a), {});
    const std::vector<bool> cb = DetectContacts(b, TimesOf(capture), Lowest(b), {});
    for (int f = 0; f < frames; ++f) agree += ca[f] == cb[f];
    total += frames;
  }
  std::printf("contacts of the fill agree with the capture's on %.1f %% of foot-frames\n", 100.0 * agree / total);
  EXPECT_GE(agree, 0.9 * total);
}

// The horizontal speed of a held foot beyond what the keys ask of it: between two keys inside
// one contact the animator may have moved the foot (the anchor follows the keys), elsewhere in
// the contact it should stand.
double SlideBeyondKeys(const std::vector<Eigen::Vector3d>& track, const MotionClip& clip, const std::vector<int>& keys,
                       int first, int last, int f) {
  Eigen::Vector3d asked = Eigen::Vector3d::Zero();
  for (size_t k = 0; k + 1 < keys.size(); ++k)
    if (keys[k] >= first && keys[k + 1] <= last && keys[k] <= f && f < keys[k + 1])
      asked = (track[keys[k + 1]] - track[keys[k]]) / (clip.time_s(keys[k + 1]) - clip.time_s(keys[k]));
  Eigen::Vector3d v = (track[f + 1] - track[f]) / (clip.time_s(f + 1) - clip.time_s(f)) - asked;
  return std::hypot(v.x(), v.z());
}

// The shipped sketch (hips and legs keyed every 8 frames) filled from the default database
// with the feet left free and planted.
struct ShippedFills {
  Result<Scene> sketch = InvalidArgument("not read");
  Result<SketchFillResult> free_fill = InvalidArgument("not run");
  Result<SketchFillResult> planted = InvalidArgument("not run");
};

ShippedFills FillShippedSketchBothWays() {
  ShippedFills out;
  out.sketch = ImportFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  if (!out.sketch.ok()) return out;
  SketchFillOptions free_options;
  free_options.plant_feet = false;
  out.free_fill = FillSketch(*out.sketch, testing::DefaultDb(), free_options);
  out.planted = FillSketch(*out.sketch, testing::DefaultDb(), {});
  return out;
}

// --feet plant (the default): during every heel contact the planter reports, the foot joint
// stands (mean horizontal speed beyond what the keys ask under 2 cm/s; the free fill slides),
// keys stay exact, the correction is zero at every key, and the legs do not pop (no larger
// frame-to-frame turn than the free fill's plus 5 degrees).
TEST(FootPlant, PlantedFeetStandDuringContacts) {
  const ShippedFills fills = FillShippedSketchBothWays();
  ASSERT_TRUE(fills.sketch.ok() && fills.free_fill.ok() && fills.planted.ok());
  const Result<Scene>& sketch = fills.sketch;
  const Result<SketchFillResult>& free_fill = fills.free_fill;
  const Result<SketchFillResult>& planted = fills.planted;
  EXPECT_TRUE(free_fill->feet.contacts.empty());
  ASSERT_GE(planted->feet.contacts.size(), 10u);
  EXPECT_LT(planted->key_error_max_deg, kPlantedKeysToleranceDeg);
  const Skeleton& s = planted->scene.skeleton;
  const MotionClip& out = planted->scene.clips[0];
  const MotionClip& loose = free_fill->scene.clips[0];
  double planted_sum = 0.0, free_sum = 0.0;
  int frames = 0;
  for (const FootContact& c : planted->feet.contacts) {
    if (c.part != "heel") continue;
    const bool left = c.side == "left";
    const int foot = *s.Find(left ? "Foot_L" : "Foot_R");
    std::vector<int> keys;
    for (double t : RotationKeysOf(sketch->clips[0], *s.Find(left ? "UpperLeg_L" : "UpperLeg_R")).times_s)
      keys.push_back(NearestFrame(out, t));
    const std::vector<Eigen::Vector3d> held = TrackOf(s, out, foot), slid = TrackOf(s, loose, foot);
    const int first = NearestFrame(out, c.start_s), last = NearestFrame(out, c.end_s);
    for (int f = first; f < last; ++f) {
      planted_sum += SlideBeyondKeys(held, out, keys, first, last, f);
      free_sum += SlideBeyondKeys(slid, loose, keys, first, last, f);
      ++frames;
    }
  }
  ASSERT_GT(frames, 50);
  std::printf("heel contacts: %d frames, foot sliding beyond the keys %.2f cm/s planted, %.2f cm/s free; "
              "%d leg-frames corrected\n",
              frames, 100.0 * planted_sum / frames, 100.0 * free_sum / frames, planted->feet.frames_held);
  EXPECT_LT(planted_sum / frames, 0.02);
  EXPECT_GT(free_sum / frames, 0.05);  // the free fill did slide: the test can fail
  EXPECT_LT(planted->max_frame_jump_deg, free_fill->max_frame_jump_deg + 5.0);
  ASSERT_EQ(planted->feet.legs.size(), 2u);
  for (const PlantedLeg& leg : planted->feet.legs) {
    ASSERT_EQ(static_cast<int>(leg.correction_m.size()), out.num_frames);
    const int thigh = *s.Find(leg.side == "left" ? "UpperLeg_L" : "UpperLeg_R");
    for (double t : RotationKeysOf(sketch->clips[0], thigh).times_s)
      EXPECT_EQ(leg.correction_m[NearestFrame(out, t)], 0.0) << leg.side << " at " << t << " s";
  }
}

// Planting keeps every frame's heel and toe at or above their floor, the lowest height the
// leg's keys give them (the slerped legs of the free fill sink below it between keys).
TEST(FootPlant, FeetStayAboveTheKeyedFloor) {
  const ShippedFills fills = FillShippedSketchBothWays();
  ASSERT_TRUE(fills.sketch.ok() && fills.free_fill.ok() && fills.planted.ok());
  const Result<Scene>& sketch = fills.sketch;
  const Result<SketchFillResult>& free_fill = fills.free_fill;
  const Result<SketchFillResult>& planted = fills.planted;
  const Skeleton& s = planted->scene.skeleton;
  double planted_depth = 0.0, free_depth = 0.0;
  for (const char* side : {"L", "R"}) {
    std::vector<int> keys;
    for (double t : RotationKeysOf(sketch->clips[0], *s.Find(std::string("UpperLeg_") + side)).times_s)
      keys.push_back(NearestFrame(planted->scene.clips[0], t));
    ASSERT_GT(keys.size(), 10u);
    for (const std::string& joint : {std::string("Foot_") + side, std::string("Toes_") + side}) {
      const std::vector<Eigen::Vector3d> held = TrackOf(s, planted->scene.clips[0], *s.Find(joint));
      const std::vector<Eigen::Vector3d> loose = TrackOf(s, free_fill->scene.clips[0], *s.Find(joint));
      double floor = INFINITY;
      for (int k : keys) floor = std::min(floor, held[k].y());
      for (size_t f = 0; f < held.size(); ++f) {
        planted_depth = std::max(planted_depth, floor - held[f].y());
        free_depth = std::max(free_depth, floor - loose[f].y());
      }
    }
  }
  std::printf("deepest below the keyed floor: %.2f mm planted, %.2f mm free\n", 1000 * planted_depth, 1000 * free_depth);
  EXPECT_LT(planted_depth, 0.001);
  EXPECT_GT(free_depth, 0.005);  // the free fill does sink: the test can fail
}

// How fast `clip`'s heels and toes move horizontally over the steps where both frames are
// within 1 cm of their floor (each joint's lowest height at the leg's keys), pooled (cm/s), as
// `eval`'s floor glide measures it against the capture's floors.
double GlideOverKeyedFloors(const Skeleton& s, const MotionClip& sketch, const MotionClip& clip) {
  double sum = 0.0;
  long steps = 0;
  for (const char* side : {"L", "R"}) {
    std::vector<int> keys;
    for (double t : RotationKeysOf(sketch, *s.Find(std::string("UpperLeg_") + side)).times_s)
      keys.push_back(NearestFrame(clip, t));
    for (const std::string& joint : {std::string("Foot_") + side, std::string("Toes_") + side}) {
      const std::vector<Eigen::Vector3d> track = TrackOf(s, clip, *s.Find(joint));
      double floor = INFINITY;
      for (int k : keys) floor = std::min(floor, track[k].y());
      for (size_t f = 0; f + 1 < track.size(); ++f) {
        if (track[f].y() > floor + 0.01 || track[f + 1].y() > floor + 0.01) continue;
        const double dt = clip.time_s(static_cast<int>(f) + 1) - clip.time_s(static_cast<int>(f));
        sum += std::hypot(track[f + 1].x() - track[f].x(), track[f + 1].z() - track[f].z()) / dt;
        ++steps;
      }
    }
  }
  return steps ? 100.0 * sum / steps : 0.0;
}

// The shipped sketch (legs keyed every 8 frames): between keys the slerped legs flatten the
// swing, so feet in flight skimmed the floor; planted with swing clearance they clear it, so
// far less foot motion happens on the floor (measured: 14.25 -> 1.91 cm/s), the keys stay exact
// and the legs do not pop (no larger frame-to-frame turn than without, plus a degree).
TEST(FootPlant, SwingingFeetClearTheFloorBetweenSparseKeys) {
  const ShippedFills fills = FillShippedSketchBothWays();
  ASSERT_TRUE(fills.sketch.ok() && fills.planted.ok());
  SketchFillOptions options;
  options.feet.swing.clearance_m = 0.0;
  const Result<SketchFillResult> flat = FillSketch(*fills.sketch, testing::DefaultDb(), options);
  ASSERT_TRUE(flat.ok()) << flat.status().message();
  const Skeleton& s = fills.planted->scene.skeleton;
  const MotionClip& sketch = fills.sketch->clips[0];
  const double cleared = GlideOverKeyedFloors(s, sketch, fills.planted->scene.clips[0]);
  const double skimming = GlideOverKeyedFloors(s, sketch, flat->scene.clips[0]);
  std::printf("feet on the keyed floor move at %.2f cm/s with swing clearance, %.2f without; largest frame-to-frame "
              "turn %.2f / %.2f degrees\n",
              cleared, skimming, fills.planted->max_frame_jump_deg, flat->max_frame_jump_deg);
  EXPECT_LT(fills.planted->key_error_max_deg, kPlantedKeysToleranceDeg);
  EXPECT_LT(cleared, 0.5 * skimming);
  EXPECT_LT(fills.planted->max_frame_jump_deg, flat->max_frame_jump_deg + 1.0);
}

// The database's own foot contacts, which the fill votes for synthesised feet: on the default
// database's walks each foot and toe stands for part of the stride and both feet are rarely
// in the air at once (walking has no flight phase); the knees, eligible too, never stand.
TEST(GroundContacts, DatabaseFeetStandInTurn) {
  const MotionDatabase& db = testing::DefaultDb();
  std::vector<std::uint8_t> eligible(db.num_joints(), 0);
  for (const char* name : {"LowerLeg_L", "Foot_L", "Toes_L", "LowerLeg_R", "Foot_R", "Toes_R"})
    eligible[*db.skeleton().Find(name)] = 1;
  Result<DatabaseContacts> contacts = FindDatabaseContacts(db, eligible);
  ASSERT_TRUE(contacts.ok()) << contacts.status().message();
  std::vector<std::string> kept;
  for (int j : contacts->joints) kept.push_back(db.skeleton().name(j));
  EXPECT_EQ(kept, (std::vector<std::string>{"Foot_L", "Toes_L", "Foot_R", "Toes_R"}));
  ASSERT_EQ(contacts->down.rows(), db.num_frames());
  int walk_frames = 0, airborne = 0;
  Eigen::Vector4d standing = Eigen::Vector4d::Zero();
  for (int c = 0; c < db.num_clips(); ++c) {
    if (db.clip(c).name.find("walk") == std::string::npos) continue;
    for (int f = db.clip(c).first_frame; f < db.clip(c).first_frame + db.clip(c).num_frames; ++f) {
      const Eigen::Vector4d d = contacts->down.row(f).transpose().cast<double>();
      standing += d;
      airborne += d[0] + d[1] == 0 && d[2] + d[3] == 0;
      ++walk_frames;
    }
  }
  ASSERT_GT(walk_frames, 500);
  standing /= walk_frames;
  std::printf("walks: foot/toe standing shares L %.2f %.2f, R %.2f %.2f; both feet up on %.1f %% of frames\n",
              standing[0], standing[1], standing[2], standing[3], 100.0 * airborne / walk_frames);
  for (int k = 0; k < 4; ++k) {
    EXPECT_GT(standing[k], 0.2) << kept[k];
    EXPECT_LT(standing[k], 0.8) << kept[k];
  }
  EXPECT_LT(airborne, 0.1 * walk_frames);
}

// A corpus take, its sketch in a named scenario, and the corpus without the take's style, as a
// fold of leave-one-style-out sees it.
struct HeldOutSketch {
  Scene truth;
  MotionClip sketch;
  const MotionDatabase* db = nullptr;
};

Result<HeldOutSketch> MakeHeldOutSketch(const std::string& take, const std::string& scenario_name,
                                        const std::string& style) {
  ASSIGN_OR_RETURN(Scene truth, ImportFile(testing::DataPath("bandai-namco-1/data/" + take + ".bvh")));
  ASSIGN_OR_RETURN(const SketchScenario scenario, FindSketchScenario(scenario_name));
  const MotionDatabase& db = testing::BandaiDbWithout(style);
  ASSIGN_OR_RETURN(MotionClip sketch, MakeSketch(db.skeleton(), truth.clips[0], scenario.sketch));
  return HeldOutSketch{std::move(truth), std::move(sketch), &db};
}

// A held-out sketch filled with `options` and scored against its capture.
struct ScoredFill {
  FillMetrics metrics;
  double key_error_max_deg = 0.0;
  FootPlantReport feet;
};

Result<ScoredFill> FillAndScore(const HeldOutSketch& take, const SketchFillOptions& options) {
  ASSIGN_OR_RETURN(SketchFillResult filled,
                   FillSketch(Scene{take.truth.skeleton, {take.sketch}, {}, {}, {}, {}}, *take.db, options));
  ASSIGN_OR_RETURN(FillMetrics m, ScoreFill(take.truth.skeleton, take.truth.clips[0], take.sketch,
                                            filled.scene.clips[0], take.db->root_joint()));
  return ScoredFill{m, filled.key_error_max_deg, std::move(filled.feet)};
}

// Legs synthesised from the upper body (the upper-body scenario) are planted where the matched
// takes stood: the fill votes the takes' contacts through its blend, and they agree with the
// capture's own contacts more often than those found on the blended legs. During the capture's
// contacts the planted feet then stand while the free ones slide, and they stand on the
// ground rather than in it.
TEST(FootPlant, SynthesisedFeetStandWhereTheTakesStood) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<HeldOutSketch> take = MakeHeldOutSketch("dataset-1_walk_proud_001", "upper-body", "proud");
  ASSERT_TRUE(take.ok()) << take.status().message();
  const Scene* truth = &take->truth;
  const MotionClip* clip = &take->sketch;
  const MotionDatabase& db = *take->db;
  const Scene sketch{truth->skeleton, {*clip}, {}, {}, {}, {}};
  std::map<bool, Result<SketchFillResult>> fills;
  for (bool plant : {false, true}) {
    SketchFillOptions options;
    options.plant_feet = plant;
    fills.emplace(plant, FillSketch(sketch, db, options));
    ASSERT_TRUE(fills.at(plant).ok()) << fills.at(plant).status().message();
  }
  const SketchFillResult& planted = *fills.at(true);
  const SketchFillResult& loose = *fills.at(false);
  std::vector<std::string> voted;
  for (const SynthesizedContacts& c : planted.report.contacts) voted.push_back(c.joint);
  EXPECT_EQ(voted.size(), 4u);
  int from_takes = 0;
  for (const FootContact& c : planted.feet.contacts) from_takes += c.found_on == "takes";
  EXPECT_GT(from_takes, 10);
  EXPECT_LT(planted.key_error_max_deg, kPlantedKeysToleranceDeg);

  // Heel contacts: voted (the report) and found on the free fill, against the capture's.
  const MotionClip& capture = truth->clips[0];
  const Skeleton& s = truth->skeleton;
  ContactDetection capture_rule;
  capture_rule.max_speed_m_per_s = 0.3;
  int agree_voted = 0, agree_found = 0, total = 0;
  for (const char* name : {"Foot_L", "Foot_R"}) {
    const std::vector<Eigen::Vector3d> true_track = TrackOf(s, capture, *s.Find(name));
    const std::vector<bool> truth_down = DetectContacts(true_track, TimesOf(capture), Lowest(true_track), capture_rule);
    const std::vector<Eigen::Vector3d> free_track = TrackOf(s, loose.scene.clips[0], *s.Find(name));
    const std::vector<bool> found = DetectContacts(free_track, TimesOf(capture), Lowest(free_track), {});
    std::vector<bool> votes(capture.num_frames, false);
    for (const SynthesizedContacts& c : planted.report.contacts)
      if (c.joint == name)
        for (const FrameRun& run : c.runs)
          for (int f = run.first_frame; f <= run.last_frame && f < capture.num_frames; ++f) votes[f] = true;
    for (int f = 0; f < capture.num_frames; ++f) {
      agree_voted += votes[f] == truth_down[f];
      agree_found += found[f] == truth_down[f];
      ++total;
    }
  }
  Result<FillMetrics> held = ScoreFill(s, capture, *clip, planted.scene.clips[0], db.root_joint());
  Result<FillMetrics> slid = ScoreFill(s, capture, *clip, loose.scene.clips[0], db.root_joint());
  ASSERT_TRUE(held.ok() && slid.ok());
  std::printf("heel contacts agree with the capture's: voted %.1f %%, found on the free fill %.1f %%; "
              "skating during true contacts %.1f cm/s planted, %.1f cm/s free; deepest below the capture's "
              "floor %.2f cm planted, %.2f cm free\n",
              100.0 * agree_voted / total, 100.0 * agree_found / total, held->foot_skate_cm_per_s,
              slid->foot_skate_cm_per_s, held->penetration_max_cm, slid->penetration_max_cm);
  // Measured: voted 97.0 %, found 89.6 %; skating 0.5 cm/s planted, 29.9 free; deepest 0.00 cm
  // planted (the feet stand on the takes' ground), 2.86 free. Before the legs were matched on
  // the hips: voted 94.4 %, found 89.9 %, free 26.8 cm/s and 3.35 cm deep.
  EXPECT_GT(agree_voted, 0.9 * total);
  EXPECT_GT(agree_voted, agree_found + 0.03 * total);
  EXPECT_LT(held->foot_skate_cm_per_s, 5.0);  // issue 15's limit
  EXPECT_GT(slid->foot_skate_cm_per_s, 15.0);  // the free legs do slide: the test can fail
  EXPECT_LT(held->penetration_max_cm, 1.0);  // issue 15's limit
  EXPECT_GT(slid->penetration_max_cm, 2.0);  // the free legs do sink
}

// Contacts of a synthesised foot as the fill reports them, for a default-database walk standing
// in for the fill's own clip: the left heel (Foot_L) and toe (Toes_L) with the given runs.
struct VotedLeftFoot {
  MotionClip fill;
  RigMapping mapping;
  FragmentFillReport report;
  std::vector<LegForPlanting> legs;
};

VotedLeftFoot VoteLeftFoot(const std::vector<FrameRun>& heel, const std::vector<FrameRun>& toe, double ground_m) {
  const MotionDatabase& db = testing::DefaultDb();
  VotedLeftFoot out;
  out.fill = *ReconstructClip(db, 0);
  out.mapping = *MapHumanoid(db.skeleton(), {});
  const Skeleton& s = db.skeleton();
  out.report.contacts.push_back({"Foot_L", *s.Find("Foot_L"), heel, ground_m});
  out.report.contacts.push_back({"Toes_L", *s.Find("Toes_L"), toe, ground_m});
  MotionClip sketch = out.fill;
  out.legs = LegsToPlant(out.mapping, sketch);
  return out;
}

const LegForPlanting& LeftLeg(const std::vector<LegForPlanting>& legs) {
  for (const LegForPlanting& leg : legs)
    if (leg.side == "left") return leg;
  throw std::runtime_error("no left leg");
}

// A heel the blended takes lift and put down again while the toe stands throughout (a bow, a
// shift of weight) stays down: the synthesised foot stays flat. Where the toe lifts too, the
// foot steps and its heel is left as voted.
TEST(SynthesizedContacts, FootStaysFlatWhileOnlyTheHeelsVoteWavers) {
  VotedLeftFoot flat = VoteLeftFoot({{0, 9}, {20, 39}}, {{0, 39}}, 0.0);
  GiveSynthesizedContacts(flat.report, testing::DefaultDb().skeleton(), flat.fill, flat.mapping, flat.fill, flat.legs);
  const LegForPlanting& standing = LeftLeg(flat.legs);
  ASSERT_EQ(static_cast<int>(standing.heel_down.size()), flat.fill.num_frames);
  for (int f = 0; f < flat.fill.num_frames; ++f) EXPECT_EQ(standing.heel_down[f], f <= 39) << "frame " << f;

  VotedLeftFoot step = VoteLeftFoot({{0, 9}, {20, 39}}, {{0, 12}, {17, 39}}, 0.0);
  GiveSynthesizedContacts(step.report, testing::DefaultDb().skeleton(), step.fill, step.mapping, step.fill, step.legs);
  const LegForPlanting& stepping = LeftLeg(step.legs);
  for (int f = 0; f < step.fill.num_frames; ++f)
    EXPECT_EQ(stepping.heel_down[f], f <= 9 || (f >= 20 && f <= 39)) << "frame " << f;
}

// The planter is told how far the takes' ground lies above the fill's own foot over its
// contacts (their median height; its lowest height without contacts), up to 10 cm; beyond, the
// sketch stands on a ground of its own.
TEST(SynthesizedContacts, FeetAreMovedOntoTheTakesGround) {
  const MotionDatabase& db = testing::DefaultDb();
  const std::vector<FrameRun> runs{{0, 39}};
  VotedLeftFoot probe = VoteLeftFoot(runs, runs, 0.0);
  const std::vector<Eigen::Vector3d> track = TrackOf(db.skeleton(), probe.fill, *db.skeleton().Find("Foot_L"));
  std::vector<double> heights;
  for (int f = 0; f <= 39; ++f) heights.push_back(track[f].y());
  std::nth_element(heights.begin(), heights.begin() + heights.size() / 2, heights.end());
  const double median = heights[heights.size() / 2];
  for (const auto& [ground, shift] : {std::pair{median + 0.03, 0.03}, {median - 0.02, -0.02}, {median + 0.5, 0.0}}) {
    VotedLeftFoot v = VoteLeftFoot(runs, runs, ground);
    GiveSynthesizedContacts(v.report, db.skeleton(), v.fill, v.mapping, v.fill, v.legs);
    EXPECT_NEAR(LeftLeg(v.legs).heel_ground_shift_m, shift, 1e-9) << "ground " << ground;
  }
  // A foot the vote never has stand (a short dash) is measured from its lowest height instead.
  const double lowest = Lowest(track);
  VotedLeftFoot airborne = VoteLeftFoot({}, runs, lowest + 0.04);
  GiveSynthesizedContacts(airborne.report, db.skeleton(), airborne.fill, airborne.mapping, airborne.fill, airborne.legs);
  EXPECT_NEAR(LeftLeg(airborne.legs).heel_ground_shift_m, 0.04, 1e-9);
}

// A bow held out of the corpus, filled from its upper body (the upper-body scenario): the
// synthesised feet stand still and on the ground. The matched takes disagree about the heels
// there; before the feet were kept flat while the toes stood, the held heels were let go and
// caught again, and the feet, 20 - 30 cm from where the blend put them, jumped; they also
// stood on the blend's median height, below the floor. Measured with this database (every
// other style): jitter ratio 0.73 (0.79 before the legs were matched on the hips), deepest
// below the capture's floor 0.00 cm (the floor of
// each kind of foot joint is the lower side's: this capture keeps its left heel 1.5 cm above
// its right throughout, and the fill stands it flat); before, jitter 1.28 and 1.48 cm below
// each side's lowest (3.84 and 1.98 cm on the tuning half's fold, whose database holds 7 styles).
TEST(FootPlant, StandingSynthesisedFeetStayStillAndOnTheGround) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<HeldOutSketch> take = MakeHeldOutSketch("dataset-1_bow_feminine_001", "upper-body", "feminine");
  ASSERT_TRUE(take.ok()) << take.status().message();
  const Scene* truth = &take->truth;
  const MotionClip* clip = &take->sketch;
  const MotionDatabase& db = *take->db;
  Result<SketchFillResult> filled = FillSketch(Scene{truth->skeleton, {*clip}, {}, {}, {}, {}}, db, {});
  ASSERT_TRUE(filled.ok()) << filled.status().message();
  Result<FillMetrics> m = ScoreFill(truth->skeleton, truth->clips[0], *clip, filled->scene.clips[0], db.root_joint());
  ASSERT_TRUE(m.ok());
  std::printf("bow, legs synthesised: jitter ratio %.3f, skating during true contacts %.2f cm/s, deepest below "
              "the capture's floor %.2f cm, unkeyed joints %.2f cm\n",
              m->jitter_ratio, m->foot_skate_cm_per_s, m->penetration_max_cm, m->mpjpe_unkeyed_cm);
  EXPECT_LT(filled->key_error_max_deg, kPlantedKeysToleranceDeg);
  EXPECT_LT(m->jitter_ratio, 1.1);
  EXPECT_LT(m->foot_skate_cm_per_s, 5.0);   // issue 15's limit
  EXPECT_LT(m->penetration_max_cm, 1.0);    // issue 15's limit
}

// Keys every 16 frames (0.53 s) fall once or twice in each step, and the contacts found on the
// fill cover only part of the capture's. A keyed leg is also held over the contacts of the take
// that lends it its detail (the texture's take), where its keys let the foot stand: on a
// held-out walk its feet slide less during the capture's contacts than with the contacts found
// on the fill alone, and the keys stay exact.
TEST(FootPlant, SparselyKeyedFeetAlsoStandWhereTheirTexturesTakeStood) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<HeldOutSketch> take = MakeHeldOutSketch("dataset-1_walk_proud_001", "legs16", "proud");
  ASSERT_TRUE(take.ok()) << take.status().message();
  const Scene* truth = &take->truth;
  const MotionClip* clip = &take->sketch;
  const MotionDatabase& db = *take->db;
  SketchFillOptions options;
  options.plant_feet = false;
  Result<SketchFillResult> loose = FillSketch(Scene{truth->skeleton, {*clip}, {}, {}, {}, {}}, db, options);
  ASSERT_TRUE(loose.ok()) << loose.status().message();
  const MotionClip& fill = loose->scene.clips[0];  // on the database's rig and rate, as the sketch is
  const RigMapping mapping = *MapHumanoid(db.skeleton(), {});
  std::map<bool, Result<FillMetrics>> scores;
  std::map<bool, FootPlantReport> reports;
  for (bool with_takes : {false, true}) {
    std::vector<LegForPlanting> legs = LegsToPlant(mapping, *clip);
    if (with_takes) GiveSynthesizedContacts(loose->report, db.skeleton(), fill, mapping, fill, legs);
    MotionClip planted = fill;
    FootPlantOptions votes_alone;  // the keys' own stances hold much of this walk's contacts as well
    votes_alone.key_still_m_per_s = 0.0;
    votes_alone.key_stance_ahead_share = votes_alone.key_stance_behind_share = 0.0;
    votes_alone.keyed_release_m_per_s = 0.0;
    reports[with_takes] = PlantFeet(db.skeleton(), legs, votes_alone, planted);
    scores.emplace(with_takes, ScoreFill(truth->skeleton, truth->clips[0], *clip, planted, db.root_joint()));
    ASSERT_TRUE(scores.at(with_takes).ok());
    EXPECT_LT(scores.at(with_takes)->key_error_max_deg, kPlantedKeysToleranceDeg);
  }
  int from_takes = 0;
  for (const FootContact& c : reports[true].contacts) from_takes += c.found_on == "takes";
  std::printf("legs keyed every 16 frames: skating during the capture's contacts %.2f cm/s with the texture "
              "take's contacts (%d of %zu contacts), %.2f with those found on the fill; keyed joints between keys "
              "%.3f / %.3f cm\n",
              scores.at(true)->foot_skate_cm_per_s, from_takes, reports[true].contacts.size(),
              scores.at(false)->foot_skate_cm_per_s, scores.at(true)->mpjpe_keyed_between_cm,
              scores.at(false)->mpjpe_keyed_between_cm);
  EXPECT_GT(from_takes, 0);
  EXPECT_LT(scores.at(true)->foot_skate_cm_per_s, 0.8 * scores.at(false)->foot_skate_cm_per_s);
  EXPECT_LE(scores.at(true)->mpjpe_keyed_between_cm, scores.at(false)->mpjpe_keyed_between_cm * 1.01);
}

// Keys every 16 frames (0.53 s) move a walking foot faster than a standing one from key to key,
// yet it stands for much of the interval: the takes' vote holds it at the key it stands on until
// it lifts, and from where it lands until the next key. On the held-out walk whose feet slid
// most (the happy style's first, legs16) they slide less during the capture's contacts: 38.35
// cm/s, against 47.51 when the vote was dropped between any two keys that far apart; keyed
// joints between keys 8.315 cm (8.467); keys stay exact. Measured with the takes' contacts held
// up to 20 cm, without the stances at keys, with the fixed release and 128 candidates, as then
// (60 cm now: SparselyKeyedFeetAreHeldWhereTheirTakeStoodFarFromTheSlerp; stances:
// SparselyKeyedFeetStandWhileTheHipsPassOverThem). 160 candidates join this walk's fragments
// to another take whose feet stand elsewhere (57.00 cm/s, 10.392 cm; over the tuning half's
// legs16 locomotion the join changes on 5 of 56 takes and keyed joints between keys improve).
TEST(FootPlant, SparselyKeyedFeetStandAtTheKeysTheyStandOn) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<HeldOutSketch> take = MakeHeldOutSketch("dataset-1_walk_happy_001", "legs16", "happy");
  ASSERT_TRUE(take.ok()) << take.status().message();
  SketchFillOptions options;
  options.feet.max_keyed_given_correction_m = 0.2;
  options.feet.key_stance_ahead_share = options.feet.key_stance_behind_share = 0.0;  // as then
  options.feet.keyed_release_m_per_s = 0.0;
  options.fill.candidates = options.fill.blend = 128;
  Result<SketchFillResult> filled =
      FillSketch(Scene{take->truth.skeleton, {take->sketch}, {}, {}, {}, {}}, *take->db, options);
  ASSERT_TRUE(filled.ok()) << filled.status().message();
  Result<FillMetrics> m = ScoreFill(take->truth.skeleton, take->truth.clips[0], take->sketch, filled->scene.clips[0],
                                    take->db->root_joint());
  ASSERT_TRUE(m.ok());
  std::printf("happy walk, legs keyed every 16 frames: skating during the capture's contacts %.2f cm/s, keyed "
              "joints between keys %.3f cm\n", m->foot_skate_cm_per_s, m->mpjpe_keyed_between_cm);
  EXPECT_LT(m->foot_skate_cm_per_s, 0.85 * 47.51);  // 47.51: the vote dropped between such keys
  EXPECT_LT(m->mpjpe_keyed_between_cm, 8.467);
  EXPECT_LT(filled->key_error_max_deg, kPlantedKeysToleranceDeg);
}

// Keys every 16 frames slerp a walking foot far from where the take lending it its detail stood
// between them: held up to 60 cm from the fill rather than 20, the take's contacts hold on more
// of the capture's stance. On the held-out walk whose feet slid most they slide less, the keyed
// joints between keys move little (on the tuning half's legs16 locomotion they came nearer the
// capture on 20 takes and farther on 1; this walk, against the tuning styles only, unchanged),
// and the keys stay exact. Without the stances at keys and with the fixed release, as measured
// then.
TEST(FootPlant, SparselyKeyedFeetAreHeldWhereTheirTakeStoodFarFromTheSlerp) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<HeldOutSketch> take = MakeHeldOutSketch("dataset-1_walk_happy_001", "legs16", "happy");
  ASSERT_TRUE(take.ok()) << take.status().message();
  std::map<double, Result<FillMetrics>> scores;
  for (double hold : {0.2, FootPlantOptions{}.max_keyed_given_correction_m}) {
    SketchFillOptions options;
    options.feet.max_keyed_given_correction_m = hold;
    options.feet.key_stance_ahead_share = options.feet.key_stance_behind_share = 0.0;  // as measured then
    options.feet.keyed_release_m_per_s = 0.0;
    Result<SketchFillResult> filled =
        FillSketch(Scene{take->truth.skeleton, {take->sketch}, {}, {}, {}, {}}, *take->db, options);
    ASSERT_TRUE(filled.ok()) << filled.status().message();
    EXPECT_LT(filled->key_error_max_deg, kPlantedKeysToleranceDeg);
    scores.emplace(hold, ScoreFill(take->truth.skeleton, take->truth.clips[0], take->sketch, filled->scene.clips[0],
                                   take->db->root_joint()));
    ASSERT_TRUE(scores.at(hold).ok());
  }
  const FillMetrics& before = *scores.at(0.2);
  const FillMetrics& now = *scores.rbegin()->second;
  std::printf("happy walk, legs keyed every 16 frames: skating during the capture's contacts %.2f cm/s held up to "
              "20 cm, %.2f up to 60; keyed joints between keys %.3f / %.3f cm\n",
              before.foot_skate_cm_per_s, now.foot_skate_cm_per_s, before.mpjpe_keyed_between_cm,
              now.mpjpe_keyed_between_cm);
  EXPECT_LT(now.foot_skate_cm_per_s, 0.95 * before.foot_skate_cm_per_s);  // measured 35.65 against 38.35
  EXPECT_LT(now.mpjpe_keyed_between_cm, 1.05 * before.mpjpe_keyed_between_cm);  // 8.566 against 8.315
}

// Keys every 4 frames on a slow walk of a style the database lacks (the old style's second):
// the keys have each foot still through most of its stance, and the fill's contacts carried
// the hold on past the last still key to the frame before the next, where the keys have the
// foot a few centimetres on: the correction dropped from 1 - 3 cm to nothing in one frame.
// Ended at the still key, the legs are less jerky and nearer the capture between keys, and the
// feet still stand during the capture's contacts (issue 15: skating under 5 cm/s).
TEST(FootPlant, HoldsEndAtTheirStillKeysWhereTheKeysMoveTheFootOn) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<HeldOutSketch> take = MakeHeldOutSketch("dataset-1_walk_old_002", "legs4", "old");
  ASSERT_TRUE(take.ok()) << take.status().message();
  SketchFillOptions holding_on;
  holding_on.feet.end_holds_at_still_keys = false;
  const Result<ScoredFill> held = FillAndScore(*take, holding_on);
  const Result<ScoredFill> ended = FillAndScore(*take, SketchFillOptions{});
  ASSERT_TRUE(held.ok()) << held.status().message();
  ASSERT_TRUE(ended.ok()) << ended.status().message();
  EXPECT_LT(held->key_error_max_deg, kPlantedKeysToleranceDeg);
  EXPECT_LT(ended->key_error_max_deg, kPlantedKeysToleranceDeg);
  const FillMetrics& before = held->metrics;
  const FillMetrics& now = ended->metrics;
  std::printf("old walk, legs keyed every 4 frames: jitter ratio %.3f holding on, %.3f ending at the still keys; "
              "keyed joints between keys %.3f / %.3f cm; skating %.2f / %.2f cm/s\n",
              before.jitter_ratio, now.jitter_ratio, before.mpjpe_keyed_between_cm, now.mpjpe_keyed_between_cm,
              before.foot_skate_cm_per_s, now.foot_skate_cm_per_s);
  EXPECT_LT(now.jitter_ratio, 0.9 * before.jitter_ratio);                     // measured 1.466 against 1.724
  EXPECT_LT(now.mpjpe_keyed_between_cm, before.mpjpe_keyed_between_cm);      // 0.337 against 0.383 cm
  EXPECT_LT(now.foot_skate_cm_per_s, 5.0);                                   // 1.44 (1.20 holding on) cm/s
}

// A held-out take's legs16 sketch filled with `before` and with the defaults; prints the feet's
// fastest frame (times the capture's), the jitter ratio and skating of both, and checks the keys.
struct FeetBeforeAndNow {
  FillMetrics before, now;
};

Result<FeetBeforeAndNow> FillLegs16BeforeAndNow(const std::string& take_name, const std::string& style,
                                                const SketchFillOptions& before) {
  ASSIGN_OR_RETURN(const HeldOutSketch take, MakeHeldOutSketch(take_name, "legs16", style));
  ASSIGN_OR_RETURN(const ScoredFill old_fill, FillAndScore(take, before));
  ASSIGN_OR_RETURN(const ScoredFill new_fill, FillAndScore(take, SketchFillOptions{}));
  EXPECT_LT(new_fill.key_error_max_deg, kPlantedKeysToleranceDeg);
  const FillMetrics& o = old_fill.metrics;
  const FillMetrics& n = new_fill.metrics;
  std::printf("%s, legs keyed every 16 frames: fastest foot frame %.2f / %.2f times the capture's, jitter ratio %.3f / "
              "%.3f, skating %.2f / %.2f cm/s\n",
              take_name.c_str(), o.foot_peak_ratio, n.foot_peak_ratio, o.jitter_ratio, n.jitter_ratio,
              o.foot_skate_cm_per_s, n.foot_skate_cm_per_s);
  return FeetBeforeAndNow{o, n};
}

// The old style's walk backwards, legs keyed every 16 frames, against the other styles: the
// takes' vote and the keys' stances started holds a frame or two after a key (or after the
// joint's previous hold), tens of centimetres from where the key has the foot, and the foot
// crossed that in those frames (its fastest frame 7.2 times the capture's). A hold now starts
// (ends) no nearer its key than its correction can fade in at 2 m/s, nor nearer the joint's
// previous (next) hold than it can change in at 1 m/s, and a foot passing straight from one
// contact into another does not jump: the fastest frame is 2.4 times the capture's, the jitter
// ratio 3.93 -> 2.66, and the feet slide no more during the capture's contacts (16.42 -> 16.07
// cm/s).
TEST(FootPlant, KeyedHoldsStartNoNearerTheirKeyThanTheFootCanReach) {
  MOCAPFILL_REQUIRE_CORPUS();
  SketchFillOptions anywhere;
  anywhere.feet.keyed_edge_m_per_s = anywhere.feet.keyed_hold_change_m_per_s = anywhere.feet.hold_jump_m_per_s = 0.0;
  const Result<FeetBeforeAndNow> feet = FillLegs16BeforeAndNow("dataset-1_walk-back_old_001", "old", anywhere);
  ASSERT_TRUE(feet.ok()) << feet.status().message();
  EXPECT_LT(feet->now.foot_peak_ratio, 3.0);
  EXPECT_LT(feet->now.foot_peak_ratio, 0.8 * feet->before.foot_peak_ratio);
  EXPECT_LT(feet->now.jitter_ratio, feet->before.jitter_ratio);
  EXPECT_LT(feet->now.foot_skate_cm_per_s, feet->before.foot_skate_cm_per_s + 0.5);
}

// The sad style's walk to the left, legs keyed every 16 frames, against the other styles: a
// toe held where one key stood it and a heel held where the next key does overlapped, and
// where the heel's hold began the foot moved tens of centimetres in a frame (its fastest frame
// 2.9 times the capture's). Where a contact starts or ends and the correction changes faster
// than 2 m/s from one frame to the next, frames of the side with the larger correction are let
// go and the fades bridge the gap: 1.95 times, the jitter ratio 1.13 -> 1.08, skating unchanged
// (4.09 cm/s).
TEST(FootPlant, FeetPassingFromOneContactToAnotherDoNotJump) {
  MOCAPFILL_REQUIRE_CORPUS();
  SketchFillOptions jumping;
  jumping.feet.hold_jump_m_per_s = 0.0;
  const Result<FeetBeforeAndNow> feet = FillLegs16BeforeAndNow("dataset-1_walk-left_sad_001", "sad", jumping);
  ASSERT_TRUE(feet.ok()) << feet.status().message();
  EXPECT_LT(feet->now.foot_peak_ratio, 0.8 * feet->before.foot_peak_ratio);
  EXPECT_LT(feet->now.jitter_ratio, feet->before.jitter_ratio);
  EXPECT_LT(feet->now.foot_skate_cm_per_s, feet->before.foot_skate_cm_per_s + 0.2);
}

// A captured standing pose held for 33 frames with the legs keyed at frames 0, 16 and 32,
// and between the keys the left leg lifted and swung as a stepping texture would have it (up
// to 30 degrees at the hip, 50 at the knee): the keys have the foot still on the ground, so it
// stands from key to key, height included (lifted 8.4 cm and moved 9.4, it is held within 0.8
// cm); without the rule nothing holds it (9.4 cm). Shipped fixture only.
TEST(FootPlant, FootStillAtTwoKeysStandsBetweenThem) {
  Result<Scene> walk = ImportFile(testing::FixturePath("default_db/dataset-1_walk_normal_001.bvh"));
  ASSERT_TRUE(walk.ok()) << walk.status().message();
  const Skeleton& skeleton = walk->skeleton;
  const MotionClip& capture = walk->clips[0];
  const int foot = *skeleton.Find("Foot_L"), hip = *skeleton.Find("UpperLeg_L"), knee = *skeleton.Find("LowerLeg_L");
  const std::vector<Eigen::Vector3d> steps = TrackOf(skeleton, capture, foot);
  int stance = 0;
  for (int f = 0; f < capture.num_frames; ++f)
    if (steps[f].y() < steps[stance].y()) stance = f;
  MotionClip clip = MotionClip::RestPose(skeleton, 33, capture.sample_rate_hz);
  for (int f = 0; f < clip.num_frames; ++f)
    for (int j = 0; j < skeleton.num_joints(); ++j) {
      clip.rotation(f, j) = capture.rotation(stance, j);
      clip.translation(f, j) = capture.translation(stance, j);
    }
  const std::vector<Eigen::Vector3d> held = TrackOf(skeleton, clip, foot);
  for (int f = 0; f < clip.num_frames; ++f) {
    const double lift = std::sin(M_PI * (f % 16) / 16.0);
    clip.rotation(f, hip) = clip.rotation(f, hip) * Eigen::AngleAxisd(-0.52 * lift, Eigen::Vector3d::UnitZ());
    clip.rotation(f, knee) = clip.rotation(f, knee) * Eigen::AngleAxisd(0.87 * lift, Eigen::Vector3d::UnitZ());
  }
  const std::vector<Eigen::Vector3d> lifted = TrackOf(skeleton, clip, foot);
  double strayed = 0.0;
  for (int f = 0; f < clip.num_frames; ++f) strayed = std::max(strayed, (lifted[f] - held[f]).norm());
  const RigMapping mapping = *MapHumanoid(skeleton, {});
  std::map<bool, double> farthest;
  for (bool rule : {false, true}) {
    std::vector<LegForPlanting> legs = LegsToPlant(mapping, clip);
    for (LegForPlanting& leg : legs) leg.pinned_times_s = {clip.time_s(0), clip.time_s(16), clip.time_s(32)};
    FootPlantOptions options;
    if (!rule) options.key_still_m_per_s = 0.0;
    MotionClip planted = clip;
    const FootPlantReport report = PlantFeet(skeleton, legs, options, planted);
    const std::vector<Eigen::Vector3d> track = TrackOf(skeleton, planted, foot);
    for (int f = 0; f < clip.num_frames; ++f) farthest[rule] = std::max(farthest[rule], (track[f] - held[f]).norm());
    int from_keys = 0;
    for (const FootContact& c : report.contacts) from_keys += c.side == "left" && c.part == "heel" && c.found_on == "keys";
    EXPECT_EQ(from_keys, rule ? 1 : 0);
  }
  std::printf("left foot lifted %.2f cm and moved %.2f cm between keys that have it still: planted, at most %.2f cm "
              "from where the keys stand it (%.2f without the keys' stances)\n",
              100 * (lifted[8].y() - held[8].y()), 100 * strayed, 100 * farthest[true], 100 * farthest[false]);
  EXPECT_GT(lifted[8].y() - held[8].y(), 0.05);
  EXPECT_GT(farthest[false], 0.05);
  EXPECT_LT(farthest[true], 0.01);  // the stance leg nearly straight: the soft reach keeps it short of full length
}

// Keys every 16 frames on a take that stands (a wave goodbye, its feet still throughout): the
// take lending the keyed legs their detail steps between the keys, and the feet were neither
// found standing on the fill nor voted standing by that take. Where two consecutive keys have a
// foot still on the ground, it stands between them, its height included: held out against the
// corpus without its style, its feet slide at 0.45 cm/s during the capture's contacts (7.65
// without the rule), the body's jitter ratio falls from 3.11 to 1.39 and the keyed joints
// between keys come nearer the capture (1.952 -> 1.168 cm); keys stay exact. (Without the rule
// but with the stances at keys and the slow release since: 5.25 cm/s, 2.91, 1.887 cm.)
TEST(FootPlant, FeetKeyedStillStandBetweenSparseKeys) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<HeldOutSketch> take = MakeHeldOutSketch("dataset-1_byebye_normal_001", "legs16", "normal");
  ASSERT_TRUE(take.ok()) << take.status().message();
  std::map<bool, FillMetrics> scores;
  std::map<bool, int> from_keys;
  for (bool rule : {false, true}) {
    SketchFillOptions options;
    if (!rule) options.feet.key_still_m_per_s = 0.0;
    Result<ScoredFill> filled = FillAndScore(*take, options);
    ASSERT_TRUE(filled.ok()) << filled.status().message();
    EXPECT_LT(filled->key_error_max_deg, kPlantedKeysToleranceDeg);
    scores[rule] = filled->metrics;
    for (const FootContact& c : filled->feet.contacts) from_keys[rule] += c.found_on == "keys";
  }
  std::printf("standing wave goodbye, legs keyed every 16 frames: skating during the capture's contacts %.2f cm/s (%.2f "
              "without the keys' stances, %d contacts from them), jitter ratio %.3f (%.3f), keyed joints between "
              "keys %.3f cm (%.3f)\n",
              scores[true].foot_skate_cm_per_s, scores[false].foot_skate_cm_per_s, from_keys[true],
              scores[true].jitter_ratio, scores[false].jitter_ratio, scores[true].mpjpe_keyed_between_cm,
              scores[false].mpjpe_keyed_between_cm);
  EXPECT_GT(from_keys[true], 0);
  EXPECT_EQ(from_keys[false], 0);
  EXPECT_LT(scores[true].foot_skate_cm_per_s, 2.0);  // issue 15: planted feet under 2 cm/s
  EXPECT_LT(scores[true].jitter_ratio, 0.8 * scores[false].jitter_ratio);
  EXPECT_LT(scores[true].mpjpe_keyed_between_cm, scores[false].mpjpe_keyed_between_cm);
}

// The walks (forwards, backwards, left, right) of the childish and happy styles, each against
// the corpus without its style, hips and legs keyed every 16 frames, filled with `options`:
// skating pooled over the capture's contacts, mean jitter ratio, contacts held as stances at
// keys, largest key error.
struct PooledWalks {
  double skating_cm_per_s = 0.0, jitter = 0.0, key_error_max_deg = 0.0;
  int stances = 0, takes = 0;
  // Floor glide pooled over its steps, the fill's and the capture's (cm/s); the keyed joints'
  // error between keys, mean over the takes (cm).
  double glide_cm_per_s = 0.0, capture_glide_cm_per_s = 0.0, keyed_between_cm = 0.0;
};

Result<PooledWalks> FillSparselyKeyedWalks(const SketchFillOptions& options) {
  PooledWalks out;
  double contact_frames = 0.0, glide_steps = 0.0, capture_steps = 0.0;
  for (const char* style : {"childish", "happy"})
    for (const char* walk : {"walk", "walk-back", "walk-left", "walk-right"}) {
      const std::string name = std::string("dataset-1_") + walk + "_" + style + "_001";
      ASSIGN_OR_RETURN(const HeldOutSketch take, MakeHeldOutSketch(name, "legs16", style));
      ASSIGN_OR_RETURN(const ScoredFill filled, FillAndScore(take, options));
      const FillMetrics& m = filled.metrics;
      out.skating_cm_per_s += m.foot_skate_cm_per_s * m.foot_contact_frames;
      contact_frames += m.foot_contact_frames;
      out.jitter += m.jitter_ratio;
      out.glide_cm_per_s += m.floor_glide_cm_per_s * m.floor_steps;
      glide_steps += m.floor_steps;
      out.capture_glide_cm_per_s += m.capture_floor_glide_cm_per_s * m.capture_floor_steps;
      capture_steps += m.capture_floor_steps;
      out.keyed_between_cm += m.mpjpe_keyed_between_cm;
      out.key_error_max_deg = std::max(out.key_error_max_deg, filled.key_error_max_deg);
      for (const FootContact& c : filled.feet.contacts) out.stances += c.found_on == "stance";
      ++out.takes;
    }
  out.skating_cm_per_s /= contact_frames;
  out.jitter /= out.takes;
  out.glide_cm_per_s /= std::max(1.0, glide_steps);
  out.capture_glide_cm_per_s /= std::max(1.0, capture_steps);
  out.keyed_between_cm /= out.takes;
  return out;
}

// Those walks filled twice, the feet's options set by `set(rule, options)` with the rule off
// (false) and on (true).
Result<std::map<bool, PooledWalks>> FillSparselyKeyedWalksBothWays(
    const std::function<void(bool, FootPlantOptions&)>& set) {
  std::map<bool, PooledWalks> walks;
  for (bool rule : {false, true}) {
    SketchFillOptions options;
    set(rule, options.feet);
    ASSIGN_OR_RETURN(walks[rule], FillSparselyKeyedWalks(options));
  }
  return walks;
}

// Those walks: a foot the keys catch on the ground stands there while the hips pass over it
// (key_stance_*), where the slerp between keys carried it on at the mean pace. Over the
// capture's contacts of all of them the feet slide less, the jitter ratio stays within issue
// 15's limit and the keys stay exact (measured 22.82 -> 19.93 cm/s, jitter 0.788 -> 0.831,
// both with the release of fixed length, as measured then). Single takes vary either way (the
// happy walk: 35.65 -> 37.64).
TEST(FootPlant, SparselyKeyedFeetStandWhileTheHipsPassOverThem) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<std::map<bool, PooledWalks>> both = FillSparselyKeyedWalksBothWays([](bool rule, FootPlantOptions& feet) {
    feet.keyed_release_m_per_s = 0.0;
    if (!rule) feet.key_stance_ahead_share = feet.key_stance_behind_share = 0.0;
  });
  ASSERT_TRUE(both.ok()) << both.status().message();
  std::map<bool, PooledWalks>& walks = *both;
  for (bool rule : {false, true}) EXPECT_LT(walks[rule].key_error_max_deg, kPlantedKeysToleranceDeg);
  std::printf("%d walks, legs keyed every 16 frames: skating during the capture's contacts %.2f cm/s (%.2f without "
              "the stances at keys, %d contacts from them), mean jitter ratio %.3f (%.3f)\n",
              walks[true].takes, walks[true].skating_cm_per_s, walks[false].skating_cm_per_s, walks[true].stances,
              walks[true].jitter, walks[false].jitter);
  EXPECT_GT(walks[true].stances, 0);
  EXPECT_EQ(walks[false].stances, 0);
  EXPECT_LT(walks[true].skating_cm_per_s, 0.9 * walks[false].skating_cm_per_s);
  EXPECT_LT(walks[true].jitter, 1.3);
}

// Those walks again, stances at keys held: a hold the stance keeps far from the slerp, let go
// within 0.1 s, threw the foot back to the fill's. Let go no faster than 0.25 m/s (over up to
// 0.3 s, never past a key), the legs are smoother (lower jitter ratio), the feet slide no
// more and the keys stay exact (measured: jitter 0.831 -> 0.739, skating 19.93 -> 18.40 cm/s).
TEST(FootPlant, KeyedLegsLetLargeCorrectionsGoSlowly) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<std::map<bool, PooledWalks>> both = FillSparselyKeyedWalksBothWays([](bool slow, FootPlantOptions& feet) {
    if (!slow) feet.keyed_release_m_per_s = 0.0;
  });
  ASSERT_TRUE(both.ok()) << both.status().message();
  std::map<bool, PooledWalks>& walks = *both;
  for (bool slow : {false, true}) EXPECT_LT(walks[slow].key_error_max_deg, kPlantedKeysToleranceDeg);
  std::printf("%d walks, legs keyed every 16 frames: mean jitter ratio %.3f released slowly, %.3f within 0.1 s; "
              "skating during the capture's contacts %.2f / %.2f cm/s\n",
              walks[true].takes, walks[true].jitter, walks[false].jitter, walks[true].skating_cm_per_s,
              walks[false].skating_cm_per_s);
  EXPECT_LT(walks[true].jitter, walks[false].jitter - 0.01);
  EXPECT_LT(walks[true].skating_cm_per_s, walks[false].skating_cm_per_s + 0.1);
}

// Keys every 16 frames (0.53 s) fall between most of a run's contacts, which last a few frames
// each: the takes' vote had them standing there but was dropped between keys that move the
// foot, and the feet of runs and dashes ran on through the capture's contacts. Held where a
// swing parts them from both keys' stances (keyed_mid_contact_swing_s), the happy style's run,
// dash and walk against the corpus without it slide less over the capture's contacts, the jitter
// ratio stays within issue 15's limit and the keys stay exact (measured: 25.49 -> 14.25 cm/s,
// jitter 0.676 -> 0.749).
TEST(FootPlant, SparselyKeyedRunsStandOnTheTakesContactsBetweenKeys) {
  MOCAPFILL_REQUIRE_CORPUS();
  std::map<bool, double> skating, contacts, jitter;
  const std::vector<std::string> takes = {"run", "dash", "walk"};
  for (const std::string& take : takes) {
    const std::string name = "dataset-1_" + take + "_happy_001";
    Result<HeldOutSketch> sketch = MakeHeldOutSketch(name, "legs16", "happy");
    ASSERT_TRUE(sketch.ok()) << sketch.status().message();
    for (bool rule : {false, true}) {
      SketchFillOptions options;
      if (!rule) options.feet.keyed_mid_contact_swing_s = 0.0;
      Result<ScoredFill> filled = FillAndScore(*sketch, options);
      ASSERT_TRUE(filled.ok()) << filled.status().message();
      EXPECT_LT(filled->key_error_max_deg, kPlantedKeysToleranceDeg);
      const FillMetrics& m = filled->metrics;
      skating[rule] += m.foot_skate_cm_per_s * m.foot_contact_frames;
      contacts[rule] += m.foot_contact_frames;
      jitter[rule] += m.jitter_ratio;
    }
  }
  for (bool rule : {false, true}) {
    skating[rule] /= std::max(1.0, contacts[rule]);
    jitter[rule] /= takes.size();
  }
  std::printf("happy run, dash and walk, legs keyed every 16 frames: skating during the capture's contacts %.2f cm/s "
              "(%.2f without the takes' contacts between keys), mean jitter ratio %.3f (%.3f)\n",
              skating[true], skating[false], jitter[true], jitter[false]);
  EXPECT_LT(skating[true], 0.8 * skating[false]);
  EXPECT_LT(jitter[true], 1.3);
}

// Those walks, swinging feet kept clear of the floor or not (swing.clearance_m): between keys 16
// frames apart the slerped legs flatten the swing, so a foot the capture has in the air skims
// the floor. Cleared, the feet move along the floor no faster than the capture's do (heels and
// toes roll on it), while the jitter ratio, the keyed joints' error between keys and the
// skating during the capture's contacts stay as they were and the keys exact (measured: floor
// glide 54.82 -> 4.63 cm/s against the capture's 7.85; jitter 0.739 -> 0.773; keyed joints
// 5.775 -> 5.767 cm; skating 18.40 both).
TEST(FootPlant, SparselyKeyedSwingsClearTheFloorLikeTheCapture) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<std::map<bool, PooledWalks>> both = FillSparselyKeyedWalksBothWays([](bool clear, FootPlantOptions& feet) {
    if (!clear) feet.swing.clearance_m = 0.0;
  });
  ASSERT_TRUE(both.ok()) << both.status().message();
  std::map<bool, PooledWalks>& walks = *both;
  for (bool clear : {false, true}) EXPECT_LT(walks[clear].key_error_max_deg, kPlantedKeysToleranceDeg);
  std::printf("%d walks, legs keyed every 16 frames: floor glide %.2f cm/s cleared, %.2f not, capture %.2f; jitter "
              "%.3f / %.3f; keyed joints between keys %.3f / %.3f cm; skating %.2f / %.2f cm/s\n",
              walks[true].takes, walks[true].glide_cm_per_s, walks[false].glide_cm_per_s,
              walks[true].capture_glide_cm_per_s, walks[true].jitter, walks[false].jitter,
              walks[true].keyed_between_cm, walks[false].keyed_between_cm, walks[true].skating_cm_per_s,
              walks[false].skating_cm_per_s);
  EXPECT_GT(walks[false].glide_cm_per_s, 2.0 * walks[true].capture_glide_cm_per_s);  // the test can fail
  EXPECT_LT(walks[true].glide_cm_per_s, walks[true].capture_glide_cm_per_s);
  EXPECT_LT(walks[true].jitter, std::min(1.3, walks[false].jitter + 0.05));
  EXPECT_LT(walks[true].keyed_between_cm, 1.01 * walks[false].keyed_between_cm);
  EXPECT_LT(walks[true].skating_cm_per_s, walks[false].skating_cm_per_s + 0.1);
}

// Standing takes of a style the corpus lacks, hips and legs keyed every 16 frames, feet
// planted: between two keys that have the hips still, the keyed travel keeps the keys' low band
// rather than the lead take's sway (still_root_m_per_s), so the legs under them, their feet held,
// come nearer the capture between keys; keys stay exact. Measured on the timid style's four
// (mean): keyed joints between keys 0.712 -> 0.370 cm, jitter ratio 1.221 -> 1.224 (the proud
// style's: 0.159 -> 0.144 cm, 2.323 -> 2.306).
TEST(FootPlant, StillHipsStayStillOverPlantedFeet) {
  MOCAPFILL_REQUIRE_CORPUS();
  std::vector<double> between(2, 0.0), jitter(2, 0.0);
  const std::vector<std::string> takes = {"bow_not-confident_001", "bye_not-confident_001",
                                          "byebye_not-confident_001", "guide_not-confident_001"};
  for (const std::string& name : takes) {
    Result<HeldOutSketch> take = MakeHeldOutSketch("dataset-1_" + name, "legs16", "not-confident");
    ASSERT_TRUE(take.ok()) << take.status().message();
    for (int swaying : {0, 1}) {
      SketchFillOptions options;
      if (swaying) options.fill.still_root_m_per_s = 0.0;  // before: the lead's sway wherever the root is keyed
      Result<ScoredFill> filled = FillAndScore(*take, options);
      ASSERT_TRUE(filled.ok()) << filled.status().message();
      EXPECT_LT(filled->key_error_max_deg, kPlantedKeysToleranceDeg);
      between[swaying] += filled->metrics.mpjpe_keyed_between_cm / takes.size();
      jitter[swaying] += filled->metrics.jitter_ratio / takes.size();
    }
  }
  std::printf("standing takes, legs16: keyed joints between keys %.3f cm (%.3f with the lead's sway), jitter ratio "
              "%.3f (%.3f)\n", between[0], between[1], jitter[0], jitter[1]);
  EXPECT_LT(between[0], 0.6 * between[1]);
  EXPECT_LT(jitter[0], 1.01 * jitter[1]);
}

// Synthesised legs are matched with the root's planar velocity weighing travel_weight times as
// much as the other drivers: a stance foot moves against the hips at the root's speed. A walk
// backwards with its upper body keyed takes its legs mostly from standing gestures (bye, bow,
// guide), whose feet the hips drag along; held out against the database without its style,
// with the weight its planted feet slide less during the capture's contacts and its legs are
// nearer the capture; keys stay exact. It is far from standing still: its legs' takes still
// travel at 0.31 m/s against its 0.5 (the report's travel_mps), the database holding one
// walk backwards per style. Take by take the weight varies (walk-left_proud_001: 10.8 ->
// 14.6 cm); it is the default for what it does over all held-out styles (docs/fill.md).
TEST(FootPlant, SynthesisedLegsTravelWithTheRoot) {
  MOCAPFILL_REQUIRE_CORPUS();
  Result<HeldOutSketch> take = MakeHeldOutSketch("dataset-1_walk-back_proud_001", "upper-body", "proud");
  ASSERT_TRUE(take.ok()) << take.status().message();
  const Scene sketch{take->truth.skeleton, {take->sketch}, {}, {}, {}, {}};
  std::map<int, FillMetrics> scores;
  std::map<int, double> leg_travel;  // the legs' blended takes' speed, mean over fragments
  for (int weighed : {0, 1}) {
    SketchFillOptions options;
    if (!weighed) options.fill.travel_weight = 1.0;
    Result<SketchFillResult> filled = FillSketch(sketch, *take->db, options);
    ASSERT_TRUE(filled.ok()) << filled.status().message();
    EXPECT_LT(filled->key_error_max_deg, kPlantedKeysToleranceDeg);
    int leg_fragments = 0;
    for (const FragmentSource& source : filled->report.fragments)
      if (source.group.find("Leg") != std::string::npos) {
        leg_travel[weighed] += source.travel_mps;
        ++leg_fragments;
      }
    ASSERT_GT(leg_fragments, 0);
    leg_travel[weighed] /= leg_fragments;
    Result<FillMetrics> m = ScoreFill(take->truth.skeleton, take->truth.clips[0], take->sketch, filled->scene.clips[0],
                                      take->db->root_joint());
    ASSERT_TRUE(m.ok());
    scores[weighed] = *m;
  }
  std::printf("walk backwards (0.5 m/s), legs synthesised: skating during the capture's contacts %.2f cm/s with the "
              "root's travel weighed, %.2f without; unkeyed joints %.3f / %.3f cm; the legs' takes travel at %.3f / "
              "%.3f m/s\n",
              scores[1].foot_skate_cm_per_s, scores[0].foot_skate_cm_per_s, scores[1].mpjpe_unkeyed_cm,
              scores[0].mpjpe_unkeyed_cm, leg_travel[1], leg_travel[0]);
  EXPECT_GE(leg_travel[1], leg_travel[0]);
  EXPECT_LT(scores[1].foot_skate_cm_per_s, 0.95 * scores[0].foot_skate_cm_per_s);  // measured 37.22 against 58.98
  EXPECT_LT(scores[1].mpjpe_unkeyed_cm, 0.97 * scores[0].mpjpe_unkeyed_cm);        // 10.265 against 12.278
}

// Per side (left, right) and frame: whether the leg (hip to ankle) reaches into the last 5 %
// of its length, where the soft reach acts.
std::vector<std::vector<bool>> StretchedLegs(const Skeleton& s, const MotionClip& clip) {
  const std::vector<Eigen::Vector3d> p = ComputeWorldPositions(s, clip);
  const int nj = s.num_joints();
  std::vector<std::vector<bool>> stretched;
  for (const char* side : {"_L", "_R"}) {
    const int hip = *s.Find(std::string("UpperLeg") + side), knee = *s.Find(std::string("LowerLeg") + side),
              ankle = *s.Find(std::string("Foot") + side);
    const double length = (p[knee] - p[hip]).norm() + (p[ankle] - p[knee]).norm();
    std::vector<bool> frames(clip.num_frames);
    for (int f = 0; f < clip.num_frames; ++f)
      frames[f] = (p[f * nj + ankle] - p[f * nj + hip]).norm() > 0.95 * length;
    stretched.push_back(frames);
  }
  return stretched;
}

// Largest turn of a knee from one frame to the next (degrees) over the frames `where` marks
// (either neighbour, per side), and the knees' mean jerk relative to the hips (m/s^3) over the
// whole clip.
struct KneeMotion {
  double max_turn_deg[2] = {0.0, 0.0};  // left, right
  double mean_jerk = 0.0;
};

KneeMotion KneeMotionOf(const Skeleton& s, const MotionClip& clip, const std::vector<std::vector<bool>>& where) {
  KneeMotion out;
  const std::vector<Eigen::Vector3d> p = ComputeWorldPositions(s, clip);
  const int nj = s.num_joints(), hips = *s.Find("Hips");
  const double rate = clip.sample_rate_hz;
  long count = 0;
  for (int side = 0; side < 2; ++side) {
    const int knee = *s.Find(side == 0 ? "LowerLeg_L" : "LowerLeg_R");
    for (int f = 1; f < clip.num_frames; ++f)
      if (where[side][f - 1] || where[side][f])
        out.max_turn_deg[side] = std::max(out.max_turn_deg[side],
                                          GeodesicAngle(clip.rotation(f - 1, knee), clip.rotation(f, knee)) * kDegPerRad);
    auto at = [&](int f) { return Eigen::Vector3d(p[f * nj + knee] - p[f * nj + hips]); };
    for (int f = 2; f + 1 < clip.num_frames; ++f, ++count)
      out.mean_jerk += (at(f + 1) - 3.0 * at(f) + 3.0 * at(f - 1) - at(f - 2)).norm() * rate * rate * rate;
  }
  out.mean_jerk /= std::max(1L, count);
  return out;
}

// A held foot that asks the leg to reach further than the fill had it, into the last 5 % of
// its length, is brought back along an exponential (soft reach): the knee turns ever faster as
// the leg straightens, and plain two-bone IK snapped it. Keys stay exact and the feet stand.
TEST(FootPlant, StretchedLegsReachSoftly) {
  Result<Scene> sketch = ImportFile(testing::FixturePath("sketches/walk_proud_002_legs8.glb"));
  ASSERT_TRUE(sketch.ok());
  std::map<double, Scene> filled;
  std::map<double, double> max_key_error;
  for (double soft : {0.0, 0.05}) {
    SketchFillOptions options;
    options.feet.soft_reach = soft;
    Result<SketchFillResult> r = FillSketch(*sketch, testing::DefaultDb(), options);
    ASSERT_TRUE(r.ok()) << r.status().message();
    filled[soft] = r->scene;
    max_key_error[soft] = r->key_error_max_deg;
  }
  // The frames where plain IK straightened a leg, compared in both fills.
  const Skeleton& s = filled[0.0].skeleton;
  const std::vector<std::vector<bool>> stretched = StretchedLegs(s, filled[0.0].clips[0]);
  std::map<double, KneeMotion> knees;
  for (double soft : {0.0, 0.05}) knees[soft] = KneeMotionOf(s, filled[soft].clips[0], stretched);
  std::printf("knees where stretched: largest turn per frame (left / right) %.2f / %.2f deg hard, %.2f / %.2f soft; "
              "mean jerk %.1f m/s^3 hard, %.1f soft\n",
              knees[0.0].max_turn_deg[0], knees[0.0].max_turn_deg[1], knees[0.05].max_turn_deg[0],
              knees[0.05].max_turn_deg[1], knees[0.0].mean_jerk, knees[0.05].mean_jerk);
  EXPECT_LT(max_key_error[0.05], kPlantedKeysToleranceDeg);
  EXPECT_LT(knees[0.05].mean_jerk, 0.9 * knees[0.0].mean_jerk);
  // Where the soft reach acts the knee's fastest turn drops (right knee 16.75 -> 14.58); the
  // left knee's fastest is its straightening into a heel strike, which no stretch causes.
  for (int side = 0; side < 2; ++side) EXPECT_LE(knees[0.05].max_turn_deg[side], knees[0.0].max_turn_deg[side] + 1e-9);
  EXPECT_LT(std::min(knees[0.05].max_turn_deg[0] - knees[0.0].max_turn_deg[0],
                     knees[0.05].max_turn_deg[1] - knees[0.0].max_turn_deg[1]),
            -1.0);
}

}  // namespace
}  // namespace mocapfill
