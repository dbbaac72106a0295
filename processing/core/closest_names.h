// Suggestions for a misspelt name: the valid names nearest to it, so that an error can say
// "no joint named 'LeftUpperLeg' (closest: 'LeftUpLeg', ...)" rather than only "unknown".
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace mocapfill {

// Levenshtein distance, case-insensitive.
int EditDistance(std::string_view a, std::string_view b);

// Up to `count` of `candidates`, nearest to `name` first.
std::vector<std::string> ClosestNames(std::string_view name, const std::vector<std::string>& candidates, int count = 3);

// "'A', 'B', 'C'": the closest names quoted, for messages.
std::string QuotedClosestNames(std::string_view name, const std::vector<std::string>& candidates, int count = 3);

}  // namespace mocapfill
