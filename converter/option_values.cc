#include "converter/option_values.h"

#include <sstream>

namespace mocapfill::cli {

std::vector<std::string> SplitList(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

Result<std::vector<ComponentDial>> ParseComponentDials(const std::vector<std::string>& texts, const std::string& flag) {
  std::vector<ComponentDial> dials;
  for (const std::string& text : texts) {
    const size_t eq = text.find('=');
    ComponentDial dial;
    size_t used_index = 0, used_value = 0;
    const Status bad = InvalidArgument(flag + " '" + text + "': expected <component>=<sigmas>, e.g. 1=+2.0");
    try {
      if (eq == std::string::npos) return bad;
      dial.component = std::stoi(text.substr(0, eq), &used_index) - 1;
      dial.sigmas = std::stod(text.substr(eq + 1), &used_value);
    } catch (const std::exception&) {
      return bad;
    }
    if (used_index != eq || used_value != text.size() - eq - 1 || dial.component < 0) return bad;
    dials.push_back(dial);
  }
  return dials;
}

}  // namespace mocapfill::cli
