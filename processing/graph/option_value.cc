#include "processing/graph/option_value.h"

#include <cmath>
#include <cstdio>

namespace mocapfill::graph {

OptionValue OptionValue::Bool(bool value) {
  OptionValue v;
  v.kind = Kind::kBool;
  v.boolean = value;
  return v;
}

OptionValue OptionValue::Number(double value, bool is_integer) {
  OptionValue v;
  v.kind = Kind::kNumber;
  v.number = value;
  v.is_integer = is_integer;
  return v;
}

OptionValue OptionValue::String(std::string value) {
  OptionValue v;
  v.kind = Kind::kString;
  v.text = std::move(value);
  return v;
}

OptionValue OptionValue::Array(std::vector<OptionValue> items) {
  OptionValue v;
  v.kind = Kind::kArray;
  v.items = std::move(items);
  return v;
}

OptionValue OptionValue::Object(std::vector<std::string> keys, std::vector<OptionValue> values) {
  OptionValue v;
  v.kind = Kind::kObject;
  v.keys = std::move(keys);
  v.items = std::move(values);
  return v;
}

namespace {

std::string Quoted(const std::string& text) {
  std::string out = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string FormatNumber(double number) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%.9g", number);
  return buffer;
}

}  // namespace

std::string FormatOptionValue(const OptionValue& value) {
  switch (value.kind) {
    case OptionValue::Kind::kNull: return "null";
    case OptionValue::Kind::kBool: return value.boolean ? "true" : "false";
    case OptionValue::Kind::kNumber: return FormatNumber(value.number);
    case OptionValue::Kind::kString: return Quoted(value.text);
    case OptionValue::Kind::kArray: {
      std::string out = "[";
      for (size_t i = 0; i < value.items.size(); ++i) out += (i ? ", " : "") + FormatOptionValue(value.items[i]);
      return out + "]";
    }
    case OptionValue::Kind::kObject: {
      std::string out = "{";
      for (size_t i = 0; i < value.items.size(); ++i)
        out += (i ? ", " : "") + Quoted(value.keys[i]) + ": " + FormatOptionValue(value.items[i]);
      return out + "}";
    }
  }
  return "null";
}

const char* KindName(OptionValue::Kind kind) {
  switch (kind) {
    case OptionValue::Kind::kNull: return "null";
    case OptionValue::Kind::kBool: return "a boolean";
    case OptionValue::Kind::kNumber: return "a number";
    case OptionValue::Kind::kString: return "a string";
    case OptionValue::Kind::kArray: return "an array";
    case OptionValue::Kind::kObject: return "an object";
  }
  return "null";
}

}  // namespace mocapfill::graph
