// Option values that CLI11 hands over as text and the verbs parse themselves: comma lists.
#pragma once

#include <string>
#include <vector>

namespace mocapfill::cli {

// "a,b,,c" -> {"a", "b", "c"}: empty items are dropped.
std::vector<std::string> SplitList(const std::string& text);

}  // namespace mocapfill::cli
