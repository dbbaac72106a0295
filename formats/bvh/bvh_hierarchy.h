// The HIERARCHY section of a BVH file, parsed into plain joint records (file units, no
// scaling yet). Any number of ROOTs, any channel layout per joint, End Sites kept as data.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "formats/bvh/bvh_common.h"
#include "formats/bvh/bvh_lexer.h"
#include "processing/core/status.h"

namespace mocapfill::bvh {

struct ParsedJoint {
  std::string name;
  int parent = -1;
  Eigen::Vector3d offset = Eigen::Vector3d::Zero();  // file units
  ChannelLayout layout;
  int first_channel = 0;  // index of this joint's first value in a motion row
  std::optional<Eigen::Vector3d> end_site;
  TextLocation location;  // of the ROOT/JOINT keyword
};

struct ParsedHierarchy {
  std::vector<ParsedJoint> joints;  // in file order: parents before children
  int num_channels = 0;             // values per motion row
  std::vector<std::string> warnings;
};

// Parses from the start of the text through the MOTION keyword. Errors carry path:line:col.
Result<ParsedHierarchy> ParseHierarchy(BvhLexer& lexer);

}  // namespace mocapfill::bvh
