#include "processing/fill/synthesized_contacts.h"

#include <algorithm>

#include "processing/motion/key_fidelity.h"

namespace mocapfill {

namespace {

// One flag per frame of `planted`: whether the fill frame nearest in time is inside a run.
std::vector<bool> AtPlantedFrames(const SynthesizedContacts& contacts, const MotionClip& fill,
                                  const MotionClip& planted) {
  std::vector<bool> fill_down(fill.num_frames, false);
  for (const FrameRun& run : contacts.runs)
    for (int f = std::max(0, run.first_frame); f <= std::min(fill.num_frames - 1, run.last_frame); ++f)
      fill_down[f] = true;
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

}  // namespace

void GiveSynthesizedContacts(const FragmentFillReport& report, const MotionClip& fill, const RigMapping& db_mapping,
                             const MotionClip& planted, std::vector<LegForPlanting>& legs) {
  if (fill.num_frames < 1) return;
  for (LegForPlanting& leg : legs) {
    const bool left = leg.side == "left";
    if (const SynthesizedContacts* c =
            ContactsOf(report, db_mapping, left ? HumanoidBone::kLeftFoot : HumanoidBone::kRightFoot))
      leg.heel_down = AtPlantedFrames(*c, fill, planted);
    if (const SynthesizedContacts* c =
            ContactsOf(report, db_mapping, left ? HumanoidBone::kLeftToes : HumanoidBone::kRightToes);
        c && leg.toe >= 0)
      leg.toe_down = AtPlantedFrames(*c, fill, planted);
  }
}

}  // namespace mocapfill
