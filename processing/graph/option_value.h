// Plain option values of a processing-graph node: the JSON-like tree a pipeline file or a
// --set override gives, without any JSON library type (the graph core knows nothing of files
// or JSON; library/pipeline turns nlohmann::json into these).
#pragma once

#include <string>
#include <vector>

namespace mocapfill::graph {

struct OptionValue {
  enum class Kind { kNull, kBool, kNumber, kString, kArray, kObject };

  Kind kind = Kind::kNull;
  bool boolean = false;
  double number = 0.0;
  bool is_integer = false;           // a number written without fraction or exponent (e.g. 3)
  std::string text;                  // kString
  std::vector<OptionValue> items;    // kArray elements; kObject member values
  std::vector<std::string> keys;     // kObject member names, parallel to items

  static OptionValue Bool(bool value);
  static OptionValue Number(double value, bool is_integer);
  static OptionValue Integer(long long value) { return Number(static_cast<double>(value), true); }
  static OptionValue String(std::string value);
  static OptionValue Array(std::vector<OptionValue> items);
  static OptionValue Object(std::vector<std::string> keys, std::vector<OptionValue> values);

  bool is_null() const { return kind == Kind::kNull; }
};

// "true", "3", "0.5", "\"walk\"", "[1, 2]", "{\"1\": 2}": a compact JSON-style rendering for
// messages, --dry-run plans and documentation.
std::string FormatOptionValue(const OptionValue& value);

// "a boolean", "a number", "a string", "an array", "an object", "null".
const char* KindName(OptionValue::Kind kind);

}  // namespace mocapfill::graph
