#include "formats/name_map_json.h"

#include <nlohmann/json.hpp>

#include "formats/file_io.h"

namespace mocapfill {

Result<std::map<std::string, std::string>> ParseNameMapJson(const std::string& text, const std::string& origin,
                                                            const std::string& shape) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // parse_error, or out_of_range for a number like 1e999
    return InvalidData(origin + ": not valid JSON: " + e.what());
  }
  if (!doc.is_object()) return InvalidData(origin + ": expected a JSON object " + shape);
  std::map<std::string, std::string> out;
  for (const auto& [key, value] : doc.items()) {
    if (value.is_null()) {
      out[key] = "";
    } else if (value.is_string()) {
      out[key] = value.get<std::string>();
    } else {
      return InvalidData(origin + ": \"" + key + "\": expected a name or \"\" (or null), got " + value.dump());
    }
  }
  return out;
}

Result<std::map<std::string, std::string>> ReadNameMap(const std::string& inline_or_path, const std::string& option,
                                                       const std::string& shape) {
  ASSIGN_OR_RETURN(const InlineOrFileText map, ReadInlineJsonOrFile(inline_or_path, option));
  return ParseNameMapJson(map.text, map.origin, shape);
}

}  // namespace mocapfill
