// Maps of names written as JSON objects: a rig map {"sketch joint": "canonical bone", ...}
// (fill --map, rig show --map) and a database's joint-name map {"source name": "database
// name"} (db build --map). One reader for both: null stands for "" (the joint left unmapped).
#pragma once

#include <map>
#include <string>

#include "processing/core/status.h"

namespace mocapfill {

// What each kind of map looks like, for messages.
inline constexpr const char* kRigMapShape = "{\"joint\": \"humanoid bone or database joint\", ...}";
inline constexpr const char* kJointNameMapShape = "{\"source name\": \"database name\", ...}";

// Parses `text`. Errors (kInvalidData) start with `origin` (the option or file) and say what
// was expected: not JSON (with the parser's position), not an object (then `shape`, such as
// {"joint": "humanoid bone", ...}), a value that is neither a string nor null.
Result<std::map<std::string, std::string>> ParseNameMapJson(const std::string& text, const std::string& origin,
                                                            const std::string& shape);

// The map given inline (text starting with '{') or as a JSON file (ReadInlineJsonOrFile), parsed.
Result<std::map<std::string, std::string>> ReadNameMap(const std::string& inline_or_path, const std::string& option,
                                                       const std::string& shape);

}  // namespace mocapfill
