// Ground contacts of the database's takes, for the synthesised feet. A blend of many takes'
// legs does not show where its foot stands (it slows down at the wrong time or not at all:
// synthesised legs slid at 45 - 60 cm/s during the true contacts), but each take's own
// captured foot does: the fill votes the takes' contacts through the same blend that wrote the
// joint, and the planter (motion/foot_plant.h) holds the foot over the voted contacts.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "processing/core/motion_database.h"
#include "processing/core/status.h"
#include "processing/synthesis/fragment_fill_report.h"

namespace mocapfill {

struct DatabaseContacts {
  std::vector<int> joints;  // database joints that stand on the ground in some take
  Eigen::MatrixXf down;     // database frames x joints: 1 where the joint stands, else 0
  // Per joint: its median height (world up) over the frames it stands on, the ground of the
  // database's takes as that joint meets it.
  std::vector<double> standing_height_m;
};

// Contacts of the `eligible` joints (flags per database joint) on every clip of `db`, found on
// the captured motion (foot_contacts.h with capture's thresholds; the floor is each joint's
// lowest height in its clip), and their standing heights. Joints standing on fewer than 2 % of
// the frames are left out.
Result<DatabaseContacts> FindDatabaseContacts(const MotionDatabase& db, const std::vector<std::uint8_t>& eligible);

// The contacts of the joints in `columns` (of contacts.down) at the fill's frames, from `votes`
// (fill frames x contacts.joints: the labels blended like the joints): a joint stands where at
// least half the blend stands, tidied like detected contacts.
std::vector<SynthesizedContacts> VotedContacts(const MotionDatabase& db, const DatabaseContacts& contacts,
                                               const std::vector<int>& columns, const Eigen::MatrixXd& votes);

}  // namespace mocapfill
