// Planted feet. Keyed legs interpolated between their keys, a root interpolated linearly and
// captured texture added on top make a standing foot slide. The contacts are found on the
// filled motion itself (foot_contacts.h: the heel's and the toe's heights and speeds) or given
// with the leg (a synthesised foot's, from the database takes it was blended from), and each
// is held at an anchor on the ground (horizontally; the height stays as filled) by two-bone IK
// of its leg (two_bone_ik.h), frame by frame:
// - where the leg is keyed inside a contact, the anchor is the keyed foot (linear between two
//   keys), so the correction is zero at every key and keys stay exact;
// - elsewhere the anchor is the foot's mean position over the contact (the least correction);
// - with the heel down the foot joint is held; with the toe down as well, the foot turns so that
//   the toe meets its own anchor; with the toe alone down (heel off), the ankle follows the
//   held toe along the foot as the fill turns it;
// - the correction fades out over a few frames beyond a contact, never past a key, so nothing
//   pops where a contact starts or ends (two contacts nearer than their fades reach: it goes
//   straight from one's to the other's); a correction straightening the leg is softened near
//   full length, so the knee does not snap;
// - at every frame the foot is lifted back above the floor the keys stand on (a leg without
//   keys but with given contacts: the median height of its contacts), if it sank.
#pragma once

#include <string>
#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/core/skeleton.h"
#include "processing/motion/foot_contacts.h"
#include "processing/motion/swing_clearance.h"
#include "processing/motion/two_bone_ik.h"
#include "processing/retargeting/rig_mapping.h"

namespace mocapfill {

struct LegForPlanting {
  std::string side;    // "left" / "right", for reports
  TwoBoneChain chain;  // thigh, shin, foot
  int toe = -1;        // the foot's toe joint, -1 if the rig has none
  // Times (seconds) at which one of the chain's joints has a rotation key: the correction must
  // be zero there.
  std::vector<double> pinned_times_s;
  // Contacts known beforehand, one flag per frame of the planted clip (the matched database
  // takes' own: for a synthesised leg, in place of those found on the motion (foot_contacts.h);
  // for a keyed one, in addition to them where its keys allow); empty: found on the motion.
  std::vector<bool> heel_down, toe_down;
  // With given contacts: how far above the median height of the leg's own foot (toe) over
  // them (its lowest height if it never stands) the ground lies. A blend of takes' legs stands
  // lower or higher than the takes did.
  double heel_ground_shift_m = 0.0, toe_ground_shift_m = 0.0;
};

struct FootPlantOptions {
  ContactDetection detection;
  double fade_s = 0.1;  // the correction fades out over this beyond a contact
  // On a keyed leg a larger correction fades out no faster than this, over up to
  // `keyed_max_fade_s` (never past a key): holds the keys' stances keep far from the slerp,
  // let go over `fade_s`, threw the foot to the fill's (0: always `fade_s`).
  double keyed_release_m_per_s = 0.25;
  double keyed_max_fade_s = 0.3;
  double max_correction_m = 0.1;  // contacts needing a larger move are not held
  // Toe contacts tighter still: a toe held far behind the fill's during push-off straightens
  // the leg, and its release turned the knee faster than capture does.
  double max_toe_correction_m = 0.06;
  // Contacts given with a leg (a synthesised foot's, from the matched takes) are where a foot
  // stands, but the takes' strides differ from the keyed root's travel: they are held up to
  // this far.
  double max_given_correction_m = 0.4;
  // On a keyed leg the given contacts join those found on the motion, held up to this far;
  // between two keys that move the foot faster than `keyed_standing_speed_m_per_s` (capture's
  // standing limit) they do not hold it. Keys every 16 frames leave the foot slerped far from
  // where the take stood between them; feet the keys have standing are held by their own rule
  // (key_still_m_per_s), so a long hold no longer drags a standing leg onto a take's steps.
  double max_keyed_given_correction_m = 0.6;
  double keyed_standing_speed_m_per_s = 0.3;
  // Between two such keys a contact of the takes that touches neither key's stance is held too
  // where a swing of at least this long parts it from each (the stance's last frame or the key
  // to its first, its last to the next stance or key): keys every 16 frames fall between most
  // of a run's short contacts. Touching a key that has the foot elsewhere, it would drag the
  // key's swing (0: such contacts are not held).
  double keyed_mid_contact_swing_s = 0.05;
  // A keyed foot on the ground at two consecutive keys of its leg that moves slower than this
  // from one to the other stands between them, height included, however far the fill strays:
  // keys sparser than a step let the texture's take step there (keys every 16 frames: a
  // standing wave's feet lifted 8 cm and slid at 54 cm/s between keys that had them still).
  double key_still_m_per_s = 0.05;
  // A hold the keys have still, which the fill's contacts or the takes' vote carry on towards
  // the leg's next key (back towards its previous one), ends at its last (first) still key
  // unless it lets go at least two frames before that key: there the keys have the foot
  // elsewhere, and a hold run on to the key snapped from 1 - 3 cm to nothing at it (with keys
  // every 4 frames most of the legs' jitter), one run past it dragged the foot behind the keys.
  bool end_holds_at_still_keys = true;
  // On a keyed leg a hold's correction fades out no faster than this on the way to the key
  // beyond its edge (where it is nothing), and changes no faster than
  // `keyed_hold_change_m_per_s` from one hold of the joint to its next where no key lies
  // between them: the holds' edge frames are let go until it does. A hold the takes' vote or a
  // key's stance starts a frame or two after a key (or after another hold), far from where the
  // key has the foot, threw the foot across in those frames (keys every 16 frames). 0: off.
  double keyed_edge_m_per_s = 2.0;
  double keyed_hold_change_m_per_s = 1.0;
  // Where the foot passes from one contact straight into another (a heel's or a toe's starts or
  // ends on the next frame) and the correction changes faster than this, frames on the side with
  // the larger correction are let go until it does not (0: off).
  double hold_jump_m_per_s = 2.0;
  // A keyed foot on the ground at a key, where the fill's contacts or the takes' vote have it
  // standing, with the hips travelling faster than `key_stance_min_travel_m_per_s`, stands at
  // the key while the hips pass over it: from when they were `key_stance_ahead_share` of its
  // reach short of it until they are `key_stance_behind_share` past it (key_stances.h; keys
  // every 8 or 16 frames, not denser). Both 0: off.
  double key_stance_ahead_share = 0.2;
  double key_stance_behind_share = 0.25;
  double key_stance_min_travel_m_per_s = 0.3;
  // Corrections that stretch the leg into the last this share of its length approach full
  // length smoothly rather than snapping the knee straight (0: plain two-bone IK).
  double soft_reach = 0.05;
  // Every frame's heel and toe are kept at or above their floor (their lowest heights at the
  // leg's keys): between keys, slerped legs and a linearly interpolated root sink them. With it,
  // a swinging foot clears the floor as `swing` asks.
  bool keep_above_floor = true;
  SwingClearanceOptions swing;
};

struct FootContact {
  std::string side;
  std::string part;  // "heel" (the foot joint) or "toe"
  double start_s = 0.0;
  double end_s = 0.0;
  int keys = 0;                   // keys of the leg inside the contact (they fix its anchor)
  double max_correction_m = 0.0;  // largest IK move of the foot joint inside the contact
  // "fill": on the motion being planted; "takes": given with the leg; "keys": the leg's keys
  // have the foot still on the ground (FootPlantOptions::key_still_m_per_s); "stance": a key
  // has the foot on the ground and the hips pass over it (FootPlantOptions::key_stance_*).
  std::string found_on = "fill";
};

struct PlantedLeg {
  std::string side;
  std::vector<double> correction_m;  // per frame: how far the IK moved the foot joint
};

struct FootPlantReport {
  std::vector<FootContact> contacts;
  std::vector<PlantedLeg> legs;
  int frames_held = 0;  // leg-frames corrected (contacts and fades)
  int contacts_skipped = 0;  // found but needing more than max_correction_m (toes: max_toe_correction_m)
  double max_correction_m = 0.0;
};

// A rig's legs for planting (thigh, shin, foot and toe by its humanoid mapping), each with the
// times at which `sketch` keys one of its joints.
std::vector<LegForPlanting> LegsToPlant(const RigMapping& mapping, const MotionClip& sketch);

// Plants every leg's foot in `clip` (uniform or explicit frame times; every key time is a frame).
FootPlantReport PlantFeet(const Skeleton& skeleton, const std::vector<LegForPlanting>& legs,
                          const FootPlantOptions& options, MotionClip& clip);

}  // namespace mocapfill
