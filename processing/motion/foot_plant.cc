#include "processing/motion/foot_plant.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "processing/core/kinematics.h"
#include "processing/core/smoothstep.h"
#include "processing/motion/key_fidelity.h"
#include "processing/motion/key_stances.h"

namespace mocapfill {

namespace {

using Eigen::Quaterniond;
using Eigen::Vector3d;

struct LegTracks {
  std::vector<Vector3d> ankle, toe, hips;
};

LegTracks TrackLeg(const Skeleton& skeleton, const MotionClip& clip, const LegForPlanting& leg) {
  LegTracks tracks;
  WorldPose pose;
  const int hips = skeleton.parent(leg.chain.upper) >= 0 ? skeleton.parent(leg.chain.upper) : leg.chain.upper;
  for (int f = 0; f < clip.num_frames; ++f) {
    ComputeWorldPose(skeleton, clip, f, pose);
    tracks.ankle.push_back(pose.positions[leg.chain.end]);
    tracks.hips.push_back(pose.positions[hips]);
    if (leg.toe >= 0) tracks.toe.push_back(pose.positions[leg.toe]);
  }
  return tracks;
}

std::vector<bool> PinnedFrames(const MotionClip& clip, const LegForPlanting& leg) {
  std::vector<bool> pinned(clip.num_frames, false);
  for (double t : leg.pinned_times_s) pinned[NearestFrame(clip, t)] = true;
  return pinned;
}

// The ground under a joint: its lowest height where the animator keyed the leg (there the
// motion is the animator's), or over the whole clip where the leg is synthesised.
double FloorOf(const std::vector<Vector3d>& track, const std::vector<bool>& pinned) {
  double keyed = INFINITY, all = INFINITY;
  for (size_t f = 0; f < track.size(); ++f) {
    all = std::min(all, track[f].y());
    if (pinned[f]) keyed = std::min(keyed, track[f].y());
  }
  return std::isfinite(keyed) ? keyed : all;
}

// Where a joint is held over one contact: through its keyed positions (linear between them,
// constant beyond), or at its mean position when no key falls inside.
std::vector<Vector3d> AnchorsOf(const MotionClip& clip, const std::vector<Vector3d>& track,
                                const std::vector<bool>& pinned, int first, int last) {
  std::vector<int> keys;
  for (int f = first; f <= last; ++f)
    if (pinned[f]) keys.push_back(f);
  std::vector<Vector3d> anchors(last - first + 1);
  if (keys.empty()) {
    Vector3d mean = Vector3d::Zero();
    for (int f = first; f <= last; ++f) mean += track[f];
    std::fill(anchors.begin(), anchors.end(), mean / double(last - first + 1));
    return anchors;
  }
  for (int f = first; f <= last; ++f) {
    const auto next = std::lower_bound(keys.begin(), keys.end(), f);
    Vector3d& a = anchors[f - first];
    if (next == keys.begin()) {
      a = track[keys.front()];
    } else if (next == keys.end()) {
      a = track[keys.back()];
    } else {
      const int k0 = *(next - 1), k1 = *next;
      const double s = (clip.time_s(f) - clip.time_s(k0)) / (clip.time_s(k1) - clip.time_s(k0));
      a = track[k0] + s * (track[k1] - track[k0]);
    }
  }
  return anchors;
}

struct JointContacts {
  std::vector<bool> down;
  std::vector<Vector3d> anchor;  // per frame, where down
  std::vector<bool> keys_still;  // per frame: down because the keys have the foot still there
  std::vector<bool> key_stance;  // per frame: down because a key has it stand as the hips pass
};

bool HasKeys(const std::vector<bool>& pinned) { return std::find(pinned.begin(), pinned.end(), true) != pinned.end(); }

// The takes' vote cannot hold a keyed foot between two keys that have it move faster than a
// standing foot does (capture's 0.3 m/s): the animator's keys overrule the takes there. Where
// a foot the takes have standing at a key lifts more than twice `fade_s` before it lands for
// the next (room to let one hold go and take up the other without a pop: with keys every 16
// frames most often, every 8 seldom, every 4 never), it stands at the key until it lifts and
// from where it lands until the next key: keys sparser than a step fall once or twice in it
// and missed most of the capture's contacts. A contact from key to key is dropped; one the
// vote has standing away from both keys only where less than `mid_swing_s` parts it from a
// key's stance or the key (FootPlantOptions::keyed_mid_contact_swing_s).
void DropVotesTheKeysDeny(const std::vector<Vector3d>& track, const std::vector<double>& times,
                          const std::vector<bool>& pinned, double standing_speed, double fade_s,
                          double mid_swing_s, std::vector<bool>& voted) {
  int previous = -1;
  for (int f = 0; f < static_cast<int>(track.size()); ++f) {
    if (!pinned[f]) continue;
    if (previous >= 0) {
      const Vector3d d = track[f] - track[previous];
      if (std::hypot(d.x(), d.z()) > standing_speed * (times[f] - times[previous])) {
        int lifts = previous, lands = f;  // the vote's stance runs from the keys inwards
        if (voted[previous])
          while (lifts + 1 < f && voted[lifts + 1]) ++lifts;
        if (voted[f])
          while (lands - 1 > previous && voted[lands - 1]) --lands;
        if (times[lands] - times[lifts] <= 2.0 * fade_s) lifts = previous, lands = f;  // no room to swing
        const std::vector<bool> between(voted.begin() + lifts + 1, voted.begin() + lands);
        for (const auto& [a, b] : ContactRuns(between)) {
          const int first = lifts + 1 + a, last = lifts + 1 + b;
          const bool apart = mid_swing_s > 0.0 && times[first] - times[lifts] >= mid_swing_s &&
                             times[lands] - times[last] >= mid_swing_s;
          if (!apart) std::fill(voted.begin() + first, voted.begin() + last + 1, false);
        }
      }
    }
    previous = f;
  }
}

// Frames from one key of the leg to the next where the joint is on its floor at both and moves
// slower than `speed` from one to the other: the animator keyed it standing there.
std::vector<bool> StillBetweenKeys(const std::vector<Vector3d>& track, const std::vector<double>& times,
                                   const std::vector<bool>& pinned, double floor, double max_height, double speed) {
  std::vector<bool> still(track.size(), false);
  int previous = -1;
  for (int f = 0; f < static_cast<int>(track.size()); ++f) {
    if (!pinned[f]) continue;
    if (previous >= 0) {
      const Vector3d d = track[f] - track[previous];
      const bool low = track[f].y() <= floor + max_height && track[previous].y() <= floor + max_height;
      if (low && std::hypot(d.x(), d.z()) <= speed * (times[f] - times[previous]))
        std::fill(still.begin() + previous, still.begin() + f + 1, true);
    }
    previous = f;
  }
  return still;
}

// FootPlantOptions::end_holds_at_still_keys. The keys' still span begins and ends on a key,
// where the hold's correction is zero; past it the keys have the foot move to the next key.
// The contact's frames beyond the span are let go unless they end (begin) at least two frames
// short of that key: one frame at least to fade the correction out before the key.
void EndHoldsAtTheirStillKeys(const std::vector<bool>& pinned, const std::vector<bool>& keys_still,
                              std::vector<bool>& down) {
  const int n = static_cast<int>(down.size());
  for (const auto& [first, last] : ContactRuns(down)) {
    int still_first = -1, still_last = -1;
    for (int f = first; f <= last; ++f)
      if (keys_still[f]) {
        if (still_first < 0) still_first = f;
        still_last = f;
      }
    if (still_first < 0) continue;
    int next = still_last + 1, previous = still_first - 1;
    while (next < n && !pinned[next]) ++next;
    while (previous >= 0 && !pinned[previous]) --previous;
    if (last > still_last && next < n && last >= next - 1)
      std::fill(down.begin() + still_last + 1, down.begin() + last + 1, false);
    if (first < still_first && previous >= 0 && first <= previous + 1)
      std::fill(down.begin() + first, down.begin() + still_first, false);
  }
}

bool Marked(const std::vector<bool>& flags, int first, int last) {
  return std::find(flags.begin() + first, flags.begin() + last + 1, true) != flags.begin() + last + 1;
}

// One contact to be held: its frames and where the joint is held at each.
struct Hold {
  int first = 0, last = -1;
  std::vector<Vector3d> anchors;  // [f - first]
  bool keys_still = false;        // the keys have the foot still in it: its height is held too
};

// How far the hold moves the joint at frame f (along the ground unless the keys hold its height).
Vector3d CorrectionAt(const Hold& hold, const std::vector<Vector3d>& track, int f) {
  Vector3d d = hold.anchors[f - hold.first] - track[f];
  if (!hold.keys_still) d.y() = 0.0;
  return d;
}

// A hold without keys inside is anchored at its mean: after its frames change, so does that.
void Reanchor(const MotionClip& clip, const std::vector<Vector3d>& track, const std::vector<bool>& pinned,
              Hold& hold) {
  hold.anchors = AnchorsOf(clip, track, pinned, hold.first, hold.last);
}

// FootPlantOptions::keyed_edge_m_per_s. At a hold's edge the correction fades out towards the
// leg's key beyond it and is nothing at the key: a hold starting a frame or two after a key, far
// from where the key has the foot, threw the foot there in those frames. Each edge moves inwards until
// its correction fades out no faster than `per_s` on the way to the key; frames the keys pin
// inside the hold stop it (their correction is nothing). False: nothing is left of the hold.
bool MoveEdgesWhereTheKeysReach(const MotionClip& clip, const std::vector<double>& times,
                                const std::vector<Vector3d>& track, const std::vector<bool>& pinned, double per_s,
                                Hold& hold) {
  const int n = static_cast<int>(track.size());
  const auto reachable = [&](int f, int key) {
    return CorrectionAt(hold, track, f).norm() <= per_s * std::abs(times[f] - times[key]);
  };
  int previous = hold.first - 1, next = hold.last + 1;
  while (previous >= 0 && !pinned[previous]) --previous;
  while (next < n && !pinned[next]) ++next;
  int from = hold.first, to = hold.last;
  if (previous >= 0)
    while (from <= to && !pinned[from] && !reachable(from, previous)) ++from;
  if (next < n)
    while (to >= from && !pinned[to] && !reachable(to, next)) --to;
  if (from > to) return false;
  if (from != hold.first || to != hold.last) {
    hold.first = from, hold.last = to;
    Reanchor(clip, track, pinned, hold);
  }
  return true;
}

// Two holds of the joint with no key between them: the correction changes from the first's
// last frame to the second's first no faster than `per_s` (as towards a key). Where it would
// not, the edge with the larger correction moves inwards a frame at a time: a heel held up to
// the frame before the toe's next hold began elsewhere (keyed stances two steps apart) threw
// the foot across in one frame.
void SpaceHoldsApart(const MotionClip& clip, const std::vector<double>& times, const std::vector<Vector3d>& track,
                     const std::vector<bool>& pinned, double per_s, std::vector<Hold>& holds) {
  for (size_t i = 0; i + 1 < holds.size(); ++i) {
    Hold& a = holds[i];
    Hold& b = holds[i + 1];
    if (b.first - a.last >= 2 && Marked(pinned, a.last + 1, b.first - 1)) continue;  // the key rule holds there
    const int a_last = a.last, b_first = b.first;
    while (a.first <= a.last && b.first <= b.last) {
      const Vector3d ca = CorrectionAt(a, track, a.last), cb = CorrectionAt(b, track, b.first);
      if ((cb - ca).norm() <= per_s * (times[b.first] - times[a.last])) break;
      const bool move_a = ca.norm() >= cb.norm();
      if (pinned[move_a ? a.last : b.first]) break;
      if (move_a) {
        --a.last;
        a.anchors.pop_back();
      } else {
        ++b.first;
        b.anchors.erase(b.anchors.begin());
      }
    }
    if (a.last != a_last && a.first <= a.last) Reanchor(clip, track, pinned, a);
    if (b.first != b_first && b.first <= b.last) Reanchor(clip, track, pinned, b);
  }
  holds.erase(std::remove_if(holds.begin(), holds.end(), [](const Hold& h) { return h.first > h.last; }), holds.end());
}

JointContacts FindContacts(const MotionClip& clip, const std::vector<Vector3d>& track, const std::vector<Vector3d>& hips,
                           const std::vector<bool>& pinned, const std::vector<bool>& given,
                           const FootPlantOptions& options, const std::string& side, const std::string& part,
                           FootPlantReport& report) {
  std::vector<double> times(clip.num_frames);
  for (int f = 0; f < clip.num_frames; ++f) times[f] = clip.time_s(f);
  const bool is_given = given.size() == track.size();
  const bool keyed = HasKeys(pinned);
  std::vector<bool> voted = is_given ? given : std::vector<bool>(track.size(), false);
  if (is_given && keyed)
    DropVotesTheKeysDeny(track, times, pinned, options.keyed_standing_speed_m_per_s, options.fade_s,
                         options.keyed_mid_contact_swing_s, voted);
  const double floor = FloorOf(track, pinned);
  JointContacts out{is_given && !keyed ? voted : DetectContacts(track, times, floor, options.detection, &hips),
                    std::vector<Vector3d>(track.size(), Vector3d::Zero()), std::vector<bool>(track.size(), false),
                    std::vector<bool>(track.size(), false)};
  if (is_given && keyed)
    for (size_t f = 0; f < out.down.size(); ++f) out.down[f] = out.down[f] || voted[f];
  if (keyed && options.key_still_m_per_s > 0.0)
    out.keys_still = StillBetweenKeys(track, times, pinned, floor, options.detection.max_height_m,
                                      options.key_still_m_per_s);
  if (keyed) {  // each key's stance, where the fill or the takes have the foot down at the key
    const KeyStanceOptions stance{options.key_stance_ahead_share, options.key_stance_behind_share,
                                  options.key_stance_min_travel_m_per_s, 2.0 * options.fade_s,
                                  options.key_still_m_per_s, options.detection.max_height_m};
    std::vector<bool> standing = out.down;
    if (is_given)
      for (size_t f = 0; f < standing.size(); ++f) standing[f] = standing[f] || given[f];
    out.key_stance = StancesAroundKeys(track, hips, times, pinned, standing, floor, stance);
  }
  for (size_t f = 0; f < out.down.size(); ++f) out.down[f] = out.down[f] || out.keys_still[f] || out.key_stance[f];
  if (keyed && options.end_holds_at_still_keys) EndHoldsAtTheirStillKeys(pinned, out.keys_still, out.down);
  std::vector<Hold> holds;
  for (const auto& run : ContactRuns(out.down)) {
    Hold hold{run.first, run.second, AnchorsOf(clip, track, pinned, run.first, run.second),
              Marked(out.keys_still, run.first, run.second)};
    if (keyed && options.keyed_edge_m_per_s > 0.0 &&
        !MoveEdgesWhereTheKeysReach(clip, times, track, pinned, options.keyed_edge_m_per_s, hold))
      continue;
    double farthest = 0.0;
    for (int f = hold.first; f <= hold.last; ++f) {
      const Vector3d d = hold.anchors[f - hold.first] - track[f];
      farthest = std::max(farthest, std::hypot(d.x(), d.z()));
    }
    // A foot this far from where it would be held is not standing (a swing foot passing low
    // and slow near a key): holding it would drag the leg and pop where the hold ends. Where
    // the keys have it still, the fill strayed and the keys hold.
    const double limit = hold.keys_still         ? INFINITY
                         : is_given && keyed ? options.max_keyed_given_correction_m
                         : is_given          ? options.max_given_correction_m
                         : part == "toe"     ? options.max_toe_correction_m
                                             : options.max_correction_m;
    if (farthest > limit) {
      ++report.contacts_skipped;
      continue;
    }
    holds.push_back(std::move(hold));
  }
  if (keyed && options.keyed_hold_change_m_per_s > 0.0)
    SpaceHoldsApart(clip, times, track, pinned, options.keyed_hold_change_m_per_s, holds);
  std::fill(out.down.begin(), out.down.end(), false);
  for (const Hold& hold : holds) {
    const int first = hold.first, last = hold.last;
    std::fill(out.down.begin() + first, out.down.begin() + last + 1, true);
    std::copy(hold.anchors.begin(), hold.anchors.end(), out.anchor.begin() + first);
    FootContact c{side, part, times[first], times[last], 0, 0.0,
                  hold.keys_still                        ? "keys"
                  : Marked(out.key_stance, first, last) ? "stance"
                  : Marked(voted, first, last)          ? "takes"
                                                        : "fill"};
    for (int f = first; f <= last; ++f) c.keys += pinned[f] ? 1 : 0;
    report.contacts.push_back(c);
  }
  return out;
}

// A toe contact without keys of its own that begins while the heel is held takes its anchor
// from the held heel: the foot lands flat and stays so, and when the heel lifts the ankle
// turns about the toe where it stood, without a jump from one anchor to the other.
void AnchorToesOnHeels(const std::vector<bool>& pinned, const LegTracks& tracks, const JointContacts& heel,
                       JointContacts& toe) {
  for (const auto& [first, last] : ContactRuns(toe.down)) {
    bool keyed = false;
    int landing = -1;
    for (int f = first; f <= last; ++f) {
      keyed = keyed || pinned[f];
      if (landing < 0 && heel.down[f]) landing = f;
    }
    if (keyed || landing < 0) continue;
    const Vector3d anchor = heel.anchor[landing] + (tracks.toe[landing] - tracks.ankle[landing]);
    for (int f = first; f <= last; ++f) toe.anchor[f] = anchor;
  }
}

// The move of the foot joint (world translation) and the turn of the foot (world rotation,
// applied before its own) that hold the contacts at frame f.
struct Correction {
  Vector3d move = Vector3d::Zero();
  Quaterniond turn = Quaterniond::Identity();
  bool any = false;
};

Correction HoldAt(int f, const LegTracks& tracks, const JointContacts& heel, const JointContacts* toe,
                  const Correction& before, double heel_off_weight) {
  Correction c;
  const bool toe_down = toe && toe->down[f];
  if (heel.down[f]) {
    c.move = heel.anchor[f] - tracks.ankle[f];
    if (toe_down) c.turn = Quaterniond::FromTwoVectors(tracks.toe[f] - tracks.ankle[f], toe->anchor[f] - heel.anchor[f]);
    c.any = true;
  } else if (toe_down) {
    // Heel off: the foot turns from where the held heel left it back to the fill's own
    // turn (a foot snapping to the fill's pitch popped by up to 30 degrees), pivoting on the toe.
    c.turn = before.any ? before.turn.slerp(heel_off_weight, Quaterniond::Identity()) : Quaterniond::Identity();
    c.move = toe->anchor[f] - tracks.ankle[f] - c.turn * (tracks.toe[f] - tracks.ankle[f]);
    c.any = true;
  }
  // Held along the ground only: the stance leg is nearly straight, where a centimetre of height
  // asks for several of knee (knees shook around the keys), while sliding is horizontal. Where
  // the keys have the foot still, its height is theirs too (the fill lifted it in a step); a
  // heel held beside such a toe keeps its height with it (free, the ankle dropped 4 cm in one
  // frame where the heel lifted and the toe's height took over).
  const bool toe_keys_height = toe_down && toe->keys_still[f];
  const bool keys_height = heel.down[f] ? heel.keys_still[f] || toe_keys_height : toe_keys_height;
  if (!keys_height) c.move.y() = 0.0;
  return c;
}

// Steps of `step` frames from `from` to the first key of the leg, at most `limit` (limit + 1
// when no key comes that soon or the clip ends first): a fade or a turn must be over by then.
int StepsToKey(const std::vector<bool>& pinned, int from, int step, int limit) {
  for (int q = 1; q <= limit; ++q) {
    const int g = from + step * q;
    if (g < 0 || g >= static_cast<int>(pinned.size())) break;
    if (pinned[g]) return q;
  }
  return limit + 1;
}

// How a contact's correction is let go beyond its edge: over `frames`, or over more (up to
// `max_frames`) where the correction is larger than `per_frame` times that.
struct Release {
  int frames = 1;
  int max_frames = 1;
  double per_frame = INFINITY;  // metres

  int FramesFor(const Correction& c) const {
    const double needed = std::ceil(c.move.norm() / per_frame);
    return needed > frames ? static_cast<int>(std::min<double>(needed, max_frames)) : frames;
  }
};

// Two contacts nearer each other than their fades reach: fading out from one and in to the
// other, the correction jumped from the one's to the other's where the two fades crossed.
// The correction goes straight from one edge's to the other's across the gap instead (no key
// lies in it: a fade never passes one).
void BridgeOverlappingFades(const std::vector<Correction>& held, const std::vector<bool>& pinned,
                            const Release& release, std::vector<Correction>& out) {
  const int n = static_cast<int>(held.size());
  int previous = -1;  // the last held frame, -1 after a key or at the start
  for (int f = 0; f < n; ++f) {
    if (pinned[f] && !held[f].any) {
      previous = -1;
      continue;
    }
    if (!held[f].any) continue;
    if (previous >= 0 && f - previous > 1 &&
        f - previous <= release.FramesFor(held[previous]) + release.FramesFor(held[f])) {
      for (int g = previous + 1; g < f; ++g) {
        const double s = Smoothstep(double(g - previous) / (f - previous));
        out[g].move = (1.0 - s) * held[previous].move + s * held[f].move;
        out[g].turn = held[previous].turn.slerp(s, held[f].turn);
        out[g].any = true;
      }
    }
    previous = f;
  }
}

// Beyond a contact the correction of its edge frame fades out over the release's frames
// (smoothstep), or sooner where a key of the leg comes first: the fade then reaches zero at the
// key (the key's pose is the animator's) rather than being cut off there.
std::vector<Correction> FadeOut(const std::vector<Correction>& held, const std::vector<bool>& pinned,
                                const Release& release) {
  std::vector<Correction> out = held;
  const int n = static_cast<int>(held.size());
  for (int f = 0; f < n; ++f) {
    if (held[f].any || pinned[f]) continue;
    double best = 0.0;
    for (int dir : {-1, 1})
      for (int d = 1; d <= release.max_frames; ++d) {
        const int e = f + dir * d;
        if (e < 0 || e >= n || (pinned[e] && !held[e].any)) break;
        if (!held[e].any) continue;
        const int fade = release.FramesFor(held[e]);
        if (d > fade) break;
        const int span = StepsToKey(pinned, e, -dir, fade) - 1;  // from the contact's edge to zero weight
        const double w = Smoothstep(1.0 - double(d) / (span + 1));
        if (w > best) {
          best = w;
          out[f].move = w * held[e].move;
          out[f].turn = Quaterniond::Identity().slerp(w, held[e].turn);
          out[f].any = true;
        }
        break;
      }
  }
  BridgeOverlappingFades(held, pinned, release, out);
  return out;
}

// Where the foot passes from one contact to another from one frame to the next (a heel or a
// toe contact starts or ends) and the correction changes by more than `per_frame`: the frames on
// the side with the larger correction are let go until the change is no faster than that across
// the gap (a toe held where the previous key stood it and a heel held where the next key does,
// overlapping, threw the foot 25 cm in a frame where the heel's hold began). The frames let go
// are no longer down, for the report.
void LetGoWhereHoldsJump(double per_frame, JointContacts& heel, JointContacts* toe, std::vector<Correction>& held) {
  const int n = static_cast<int>(held.size());
  const auto changes = [&](int f) {
    return heel.down[f] != heel.down[f - 1] || (toe && toe->down[f] != toe->down[f - 1]);
  };
  const auto let_go = [&](int f) {
    held[f] = Correction{};
    heel.down[f] = false;
    if (toe) toe->down[f] = false;
  };
  for (int f = 1; f < n; ++f) {
    if (!held[f - 1].any || !held[f].any || !changes(f)) continue;
    int a = f - 1, b = f;
    while ((held[b].move - held[a].move).norm() > per_frame * (b - a)) {
      if (held[a].move.norm() >= held[b].move.norm()) {
        let_go(a--);
        if (a < 0 || !held[a].any) break;
      } else {
        let_go(b++);
        if (b >= n || !held[b].any) break;
      }
    }
    f = std::max(f, b);
  }
}

// A leg's contacts as reported: each narrowed to the frames its joint is still down (holds let
// go where they jumped no longer count), or dropped if none is; with its largest correction.
void ReportHeldContacts(const MotionClip& clip, const JointContacts& heel, const JointContacts& toe,
                        const std::vector<double>& correction_m, size_t first_contact,
                        std::vector<FootContact>& contacts) {
  size_t kept = first_contact;
  for (size_t i = first_contact; i < contacts.size(); ++i) {
    FootContact contact = contacts[i];
    const std::vector<bool>& down = contact.part == "toe" ? toe.down : heel.down;
    int first = NearestFrame(clip, contact.start_s), last = NearestFrame(clip, contact.end_s);
    while (first <= last && !down[first]) ++first;
    while (last >= first && !down[last]) --last;
    if (first > last) continue;
    contact.start_s = clip.time_s(first);
    contact.end_s = clip.time_s(last);
    for (int f = first; f <= last; ++f) contact.max_correction_m = std::max(contact.max_correction_m, correction_m[f]);
    contacts[kept++] = contact;
  }
  contacts.resize(kept);
}

// The floor of a joint given its contacts: the median height over them, or its lowest height
// if the vote never has it stand (a short dash), moved by `shift` onto the ground; never below
// `lowest`, where it would lift nothing.
double GivenFloor(const std::vector<Vector3d>& track, const std::vector<bool>& down, double lowest, double shift) {
  return std::max(lowest, StandingOrLowestHeight(track, down) + shift);
}

// The floors a leg's heel and toe are kept on: their lowest heights at the keys (keys are on or
// above them). A leg given its contacts (synthesised, without keys) stands on the median height
// of its contacts moved onto the takes' ground instead: its lowest height let a blend of takes'
// feet sink up to 5 cm below the ground it walked on, and the median alone still 1 - 5 cm.
struct LegFloors {
  double heel = -INFINITY, toe = -INFINITY;
};

LegFloors FloorsOf(const LegTracks& tracks, const std::vector<bool>& pinned, const LegForPlanting& leg) {
  LegFloors floors{FloorOf(tracks.ankle, pinned), tracks.toe.empty() ? -INFINITY : FloorOf(tracks.toe, pinned)};
  // A keyed leg stands where its keys put it: their lowest heights are its floor.
  if (HasKeys(pinned)) return floors;
  if (leg.heel_down.size() == tracks.ankle.size())
    floors.heel = GivenFloor(tracks.ankle, leg.heel_down, floors.heel, leg.heel_ground_shift_m);
  if (!tracks.toe.empty() && leg.toe_down.size() == tracks.toe.size())
    floors.toe = GivenFloor(tracks.toe, leg.toe_down, floors.toe, leg.toe_ground_shift_m);
  return floors;
}

// How far the corrected foot's ankle and toe lie below `floors` raised by `above(joint)`: the
// lift that brings both to them (<= 0: none needed).
template <typename Above>
double Shortfall(const LegTracks& tracks, const Correction& c, int f, const LegFloors& floors, Above above) {
  const Vector3d ankle = tracks.ankle[f] + c.move;
  double lift = floors.heel + above(tracks.ankle) - ankle.y();
  if (!tracks.toe.empty())
    lift = std::max(lift, floors.toe + above(tracks.toe) - (ankle + c.turn * (tracks.toe[f] - tracks.ankle[f])).y());
  return lift;
}

// Between keys the slerped legs and the linearly interpolated root can sink a foot below the
// ground the keys stand on: every frame's foot (after the holds) is lifted back onto its floors.
void LiftAboveFloor(const LegTracks& tracks, const std::vector<bool>& pinned, const LegFloors& floors,
                    std::vector<Correction>& corrections) {
  for (size_t f = 0; f < corrections.size(); ++f) {
    if (pinned[f]) continue;
    const double lift = Shortfall(tracks, corrections[f], static_cast<int>(f), floors, [](const auto&) { return 0.0; });
    if (lift <= 0.0) continue;
    corrections[f].move.y() += lift;
    corrections[f].any = true;
  }
}

// A foot no key pins and no contact holds is raised to clear its floors by the clearance its
// horizontal speed asks (swing_clearance.h), shaped in time by SwingLift.
void KeepSwingsClear(const LegTracks& tracks, const std::vector<bool>& pinned, const std::vector<Correction>& held,
                     const LegFloors& floors, double frame_s, const SwingClearanceOptions& options,
                     std::vector<Correction>& corrections) {
  const int n = static_cast<int>(corrections.size());
  std::vector<double> shortfall(n, 0.0);
  std::vector<bool> free(n);
  for (int f = 0; f < n; ++f) free[f] = !pinned[f] && !held[f].any;
  for (int f = 1; f + 1 < n; ++f) {
    if (!free[f]) continue;
    shortfall[f] = Shortfall(tracks, corrections[f], f, floors, [&](const std::vector<Vector3d>& track) {
      const Vector3d step = track[f + 1] - track[f - 1];
      const double speed = std::hypot(step.x(), step.z()) / (2.0 * frame_s);
      return options.clearance_m * std::min(1.0, speed / options.full_speed_m_per_s);
    });
  }
  const std::vector<double> lift = SwingLift(shortfall, free, pinned, frame_s, options);
  for (int f = 0; f < n; ++f) {
    if (lift[f] <= 0.0) continue;
    corrections[f].move.y() += lift[f];
    corrections[f].any = true;
  }
}

// The target brought back towards the hip where it asks the leg to reach further than the fill
// had it, into the last `soft` share of its length: a knee turns ever faster as the leg
// straightens (the angle's rate goes as 1 / sin), so a held foot a few millimetres beyond the
// straight leg snapped the knee. The reach approaches full length exponentially instead
// ("soft IK"); it is unchanged up to the fill's own reach, so a fading correction meets the
// fill without a step.
Vector3d SoftenedReach(const WorldPose& pose, const TwoBoneChain& chain, const Vector3d& target, double soft) {
  const Vector3d hip = pose.positions[chain.upper];
  const double length = (pose.positions[chain.lower] - hip).norm() +
                        (pose.positions[chain.end] - pose.positions[chain.lower]).norm();
  const double start = std::max((pose.positions[chain.end] - hip).norm(), (1.0 - soft) * length);
  const double wanted = (target - hip).norm();
  if (soft <= 0.0 || wanted <= start || start >= length) return target;
  const double room = length - start;
  return hip + (target - hip) * ((start + room * (1.0 - std::exp(-(wanted - start) / room))) / wanted);
}

}  // namespace

std::vector<LegForPlanting> LegsToPlant(const RigMapping& mapping, const MotionClip& sketch) {
  using B = HumanoidBone;
  std::vector<LegForPlanting> legs;
  for (const auto& [side, bones] :
       {std::pair{"left", std::array{B::kLeftUpperLeg, B::kLeftLowerLeg, B::kLeftFoot, B::kLeftToes}},
        std::pair{"right", std::array{B::kRightUpperLeg, B::kRightLowerLeg, B::kRightFoot, B::kRightToes}}}) {
    if (!mapping.has(bones[0]) || !mapping.has(bones[1]) || !mapping.has(bones[2])) continue;
    LegForPlanting leg{side, {mapping.joint(bones[0]), mapping.joint(bones[1]), mapping.joint(bones[2])},
                       mapping.has(bones[3]) ? mapping.joint(bones[3]) : -1, {}, {}, {}};
    for (int j : {leg.chain.upper, leg.chain.lower, leg.chain.end})
      for (double t : RotationKeysOf(sketch, j).times_s) leg.pinned_times_s.push_back(t);
    std::sort(leg.pinned_times_s.begin(), leg.pinned_times_s.end());
    legs.push_back(std::move(leg));
  }
  return legs;
}

FootPlantReport PlantFeet(const Skeleton& skeleton, const std::vector<LegForPlanting>& legs,
                          const FootPlantOptions& options, MotionClip& clip) {
  FootPlantReport report;
  if (clip.num_frames < 2) return report;
  const double frame_s = std::max(1e-9, clip.time_s(clip.num_frames - 1) - clip.time_s(0)) / (clip.num_frames - 1);
  const int fade = std::max(1, static_cast<int>(std::lround(options.fade_s / frame_s)));
  WorldPose pose;
  for (const LegForPlanting& leg : legs) {
    const LegTracks tracks = TrackLeg(skeleton, clip, leg);
    const std::vector<bool> pinned = PinnedFrames(clip, leg);
    const size_t first_contact = report.contacts.size();
    JointContacts heel =
        FindContacts(clip, tracks.ankle, tracks.hips, pinned, leg.heel_down, options, leg.side, "heel", report);
    JointContacts toe;
    if (leg.toe >= 0) {
      toe = FindContacts(clip, tracks.toe, tracks.hips, pinned, leg.toe_down, options, leg.side, "toe", report);
      AnchorToesOnHeels(pinned, tracks, heel, toe);
    }
    std::vector<Correction> held(clip.num_frames);
    // Heel off, the foot turns back over `fade` frames, or by the next key if that comes first.
    int heel_off = 0, turn_span = fade;
    for (int f = 0; f < clip.num_frames; ++f) {
      heel_off = heel.down[f] ? 0 : heel_off + 1;
      if (heel_off == 1) turn_span = StepsToKey(pinned, f - 1, 1, fade) - 1;
      if (!pinned[f])
        held[f] = HoldAt(f, tracks, heel, leg.toe >= 0 ? &toe : nullptr, f > 0 ? held[f - 1] : Correction{},
                         Smoothstep(double(heel_off) / (turn_span + 1)));
    }
    if (options.hold_jump_m_per_s > 0.0)
      LetGoWhereHoldsJump(options.hold_jump_m_per_s * frame_s, heel, leg.toe >= 0 ? &toe : nullptr, held);
    // A keyed leg lets a large correction go no faster than keyed_release_m_per_s (its fades
    // end at keys, so they stay short where keys are dense).
    Release release{fade, fade, INFINITY};
    if (HasKeys(pinned) && options.keyed_release_m_per_s > 0.0)
      release = {fade, std::max(fade, static_cast<int>(std::lround(options.keyed_max_fade_s / frame_s))),
                 options.keyed_release_m_per_s * frame_s};
    std::vector<Correction> corrections = FadeOut(held, pinned, release);
    if (options.keep_above_floor) {
      const LegFloors floors = FloorsOf(tracks, pinned, leg);
      LiftAboveFloor(tracks, pinned, floors, corrections);
      KeepSwingsClear(tracks, pinned, held, floors, frame_s, options.swing, corrections);
    }

    const Vector3d hinge = HingeOf(skeleton, clip, leg.chain);
    PlantedLeg planted{leg.side, std::vector<double>(clip.num_frames, 0.0)};
    for (int f = 0; f < clip.num_frames; ++f) {
      const Correction& c = corrections[f];
      if (!c.any) continue;
      ComputeWorldPose(skeleton, clip, f, pose);
      const Vector3d target = SoftenedReach(pose, leg.chain, pose.positions[leg.chain.end] + c.move, options.soft_reach);
      pose.rotations[leg.chain.end] = c.turn * pose.rotations[leg.chain.end];
      const TwoBoneSolution s = SolveTwoBoneIk(skeleton, pose, leg.chain, target, hinge);
      clip.rotation(f, leg.chain.upper) = s.upper;
      clip.rotation(f, leg.chain.lower) = s.lower;
      clip.rotation(f, leg.chain.end) = s.end;
      planted.correction_m[f] = c.move.norm();
      report.max_correction_m = std::max(report.max_correction_m, planted.correction_m[f]);
      ++report.frames_held;
    }
    ReportHeldContacts(clip, heel, toe, planted.correction_m, first_contact, report.contacts);
    report.legs.push_back(std::move(planted));
  }
  return report;
}

}  // namespace mocapfill
