#include "processing/fill/synthesized_contacts.h"

#include <algorithm>
#include <cmath>

#include "processing/core/kinematics.h"
#include "processing/motion/foot_contacts.h"
#include "processing/motion/key_fidelity.h"

namespace mocapfill {

namespace {

// Beyond this, the sketch stands on a ground of its own (another floor height in the user's
// scene) rather than on a blend that sank or rose: the fill's own contact height is kept.
constexpr double kMaxGroundShiftM = 0.1;

// One flag per frame of the fill: whether the frame is inside a run.
std::vector<bool> DownAtFillFrames(const SynthesizedContacts& contacts, const MotionClip& fill) {
  std::vector<bool> down(fill.num_frames, false);
  for (const FrameRun& run : contacts.runs)
    for (int f = std::max(0, run.first_frame); f <= std::min(fill.num_frames - 1, run.last_frame); ++f) down[f] = true;
  return down;
}

// One flag per frame of `planted`: whether the fill frame nearest in time is down.
std::vector<bool> AtPlantedFrames(const std::vector<bool>& fill_down, const MotionClip& fill, const MotionClip& planted) {
  std::vector<bool> down(planted.num_frames, false);
  for (int f = 0; f < planted.num_frames; ++f) down[f] = fill_down[NearestFrame(fill, planted.time_s(f))];
  return down;
}

const SynthesizedContacts* ContactsOf(const FragmentFillReport& report, const RigMapping& db_mapping,
                                      HumanoidBone bone) {
  if (!db_mapping.has(bone)) return nullptr;
  for (const SynthesizedContacts& c : report.contacts)
    if (c.joint_index == db_mapping.joint(bone)) return &c;
  return nullptr;
}

// A heel lifted and put down again while the toe stands throughout is where the blended takes
// disagree about the heel (a bow, a shifted weight), not a step: the foot stays flat. Turning
// it up onto the toe and back moved standing feet by up to 30 cm (corrections of a blend's
// feet that drift with the hips) and made them the jerkiest joints of the fill.
void KeepFlatWhileTheToeStands(std::vector<bool>& heel_down, const std::vector<bool>& toe_down) {
  const int n = static_cast<int>(heel_down.size());
  for (int f = 0; f < n;) {
    if (heel_down[f]) {
      ++f;
      continue;
    }
    int end = f;
    bool toe_stands = true;
    for (; end < n && !heel_down[end]; ++end) toe_stands = toe_stands && toe_down[end];
    if (toe_stands && f > 0 && end < n) std::fill(heel_down.begin() + f, heel_down.begin() + end, true);
    f = end;
  }
}

// How far the database's ground for the joint lies above the fill's own median height of the
// joint over its contacts, or above its lowest height when it has none (0 when beyond
// kMaxGroundShiftM). The planter measures the same on the clip it plants (foot_plant.h).
double GroundShift(const std::vector<Eigen::Vector3d>& positions, int num_joints, int joint,
                   const std::vector<bool>& down, double ground_m) {
  std::vector<Eigen::Vector3d> track(down.size());
  for (size_t f = 0; f < down.size(); ++f) track[f] = positions[f * num_joints + joint];
  const double standing = StandingOrLowestHeight(track, down);
  if (!std::isfinite(standing)) return 0.0;
  const double shift = ground_m - standing;
  return std::abs(shift) <= kMaxGroundShiftM ? shift : 0.0;
}

}  // namespace

void GiveSynthesizedContacts(const FragmentFillReport& report, const Skeleton& db_skeleton, const MotionClip& fill,
                             const RigMapping& db_mapping, const MotionClip& planted, std::vector<LegForPlanting>& legs) {
  if (fill.num_frames < 1) return;
  std::vector<Eigen::Vector3d> positions;
  for (LegForPlanting& leg : legs) {
    const bool left = leg.side == "left";
    const SynthesizedContacts* heel =
        ContactsOf(report, db_mapping, left ? HumanoidBone::kLeftFoot : HumanoidBone::kRightFoot);
    const SynthesizedContacts* toe =
        leg.toe >= 0 ? ContactsOf(report, db_mapping, left ? HumanoidBone::kLeftToes : HumanoidBone::kRightToes)
                     : nullptr;
    if (!heel && !toe) continue;
    if (positions.empty()) positions = ComputeWorldPositions(db_skeleton, fill);
    std::vector<bool> heel_down = heel ? DownAtFillFrames(*heel, fill) : std::vector<bool>{};
    const std::vector<bool> toe_down = toe ? DownAtFillFrames(*toe, fill) : std::vector<bool>{};
    if (heel && toe) KeepFlatWhileTheToeStands(heel_down, toe_down);
    if (heel) {
      leg.heel_down = AtPlantedFrames(heel_down, fill, planted);
      leg.heel_ground_shift_m =
          GroundShift(positions, db_skeleton.num_joints(), heel->joint_index, heel_down, heel->ground_height_m);
    }
    if (toe) {
      leg.toe_down = AtPlantedFrames(toe_down, fill, planted);
      leg.toe_ground_shift_m =
          GroundShift(positions, db_skeleton.num_joints(), toe->joint_index, toe_down, toe->ground_height_m);
    }
  }
}

}  // namespace mocapfill
