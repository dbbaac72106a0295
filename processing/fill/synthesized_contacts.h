// Planting synthesised feet where the matched takes stood. The fill votes the database takes'
// own foot contacts for the feet it synthesises (synthesis/ground_contacts.h) and reports them
// at its frames; the planter (motion/foot_plant.h) finds contacts on keyed feet itself, but on
// a blend of takes it would hold the foot wherever the blend happens to slow down. Keyed feet
// get their texture's take's contacts too, which the planter adds to those it finds.
#pragma once

#include <vector>

#include "processing/core/motion_clip.h"
#include "processing/motion/foot_plant.h"
#include "processing/retargeting/rig_mapping.h"
#include "processing/synthesis/fragment_fill_report.h"

namespace mocapfill {

// Gives every leg whose foot (or toe) the fill reports contacts for those contacts, at
// the frames of `planted` (the clip about to be planted, on any rig; its times in the time base
// of `fill`, the fill's own clip on the database's skeleton `db_skeleton`, whose humanoid
// mapping is `db_mapping`), with the foot kept flat where only the heel's vote wavers, and how
// far the database's ground lies above the fill's feet over those contacts.
void GiveSynthesizedContacts(const FragmentFillReport& report, const Skeleton& db_skeleton, const MotionClip& fill,
                             const RigMapping& db_mapping, const MotionClip& planted, std::vector<LegForPlanting>& legs);

}  // namespace mocapfill
