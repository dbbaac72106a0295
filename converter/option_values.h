// Option values that CLI11 hands over as text and the verbs parse themselves: comma lists
// and PCA component dials.
#pragma once

#include <string>
#include <vector>

#include "processing/core/status.h"
#include "processing/pca/pca_edit.h"

namespace mocapfill::cli {

// "a,b,,c" -> {"a", "b", "c"}: empty items are dropped.
std::vector<std::string> SplitList(const std::string& text);

// "3=-1.5" -> component 3 (1-based on the command line, 0-based in the result) moved by -1.5
// standard deviations. kInvalidArgument naming `flag` and the text on anything else.
Result<std::vector<ComponentDial>> ParseComponentDials(const std::vector<std::string>& texts, const std::string& flag);

}  // namespace mocapfill::cli
