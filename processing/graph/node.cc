#include "processing/graph/node.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace mocapfill::graph {

namespace {

std::vector<std::string> SplitCommas(const std::string& text) {
  std::vector<std::string> parts;
  if (text.empty()) return parts;
  std::stringstream stream(text);
  for (std::string part; std::getline(stream, part, ',');) parts.push_back(part);
  return parts;
}

// A number written as text, integral when it has no fraction or exponent; a string value
// otherwise, which the schema check then refuses with its own message ("expected a number").
OptionValue NumberOrText(const std::string& text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  // A leading '+' (a dial's "1=+1.5") is a sign from_chars does not take.
  const char* begin = text.size() > 1 && text[0] == '+' && text[1] != '-' ? text.data() + 1 : text.data();
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec != std::errc() || ptr != end || text.empty()) return OptionValue::String(text);
  return OptionValue::Number(value, text.find_first_of(".eE") == std::string::npos);
}

OptionValue FromText(const OptionSpec& spec, const std::string& text) {
  switch (spec.type) {
    case OptionType::kBool:
      if (spec.words.size() == 2 && text == spec.words[0]) return OptionValue::Bool(true);
      if (spec.words.size() == 2 && text == spec.words[1]) return OptionValue::Bool(false);
      if (text == "true" || text == "on" || text == "1") return OptionValue::Bool(true);
      if (text == "false" || text == "off" || text == "0") return OptionValue::Bool(false);
      return OptionValue::String(text);
    case OptionType::kInt:
    case OptionType::kNumber: return NumberOrText(text);
    case OptionType::kString:
    case OptionType::kPath: return OptionValue::String(text);
    case OptionType::kNumberList:
    case OptionType::kStringList: {
      std::vector<OptionValue> items;
      for (const std::string& part : SplitCommas(text))
        items.push_back(spec.type == OptionType::kNumberList ? NumberOrText(part) : OptionValue::String(part));
      return OptionValue::Array(std::move(items));
    }
    case OptionType::kNumberMap:
    case OptionType::kStringMap: {
      std::vector<std::string> keys;
      std::vector<OptionValue> values;
      for (const std::string& part : SplitCommas(text)) {
        const size_t eq = part.find('=');
        const std::string value = eq == std::string::npos ? "" : part.substr(eq + 1);
        keys.push_back(part.substr(0, eq));
        values.push_back(spec.type == OptionType::kNumberMap ? NumberOrText(value) : OptionValue::String(value));
      }
      return OptionValue::Object(std::move(keys), std::move(values));
    }
  }
  return OptionValue::String(text);
}

}  // namespace

Result<OptionValue> OptionValueFromText(const OptionSpec& spec, const std::string& text, const std::string& label) {
  if (spec.type == OptionType::kNumberMap || spec.type == OptionType::kStringMap)
    for (const std::string& item : SplitCommas(text))
      if (item.find('=') == std::string::npos)
        return InvalidArgument(label + ": \"" + item + "\": expected <key>=<value>, e.g. " +
                               (spec.type == OptionType::kNumberMap ? "1=+2.0" : "Hip=hips"));
  return FromText(spec, text);
}

const char* PortTypeName(PortType type) {
  switch (type) {
    case PortType::kMotion: return "motion";
    case PortType::kDatabase: return "database";
    case PortType::kPcaModel: return "pca_model";
  }
  return "?";
}

PortType TypeOf(const Value& value) { return static_cast<PortType>(value.index()); }

const char* OptionTypeName(OptionType type) {
  switch (type) {
    case OptionType::kBool: return "bool";
    case OptionType::kInt: return "int";
    case OptionType::kNumber: return "number";
    case OptionType::kString: return "string";
    case OptionType::kPath: return "path";
    case OptionType::kNumberList: return "number list";
    case OptionType::kStringList: return "string list";
    case OptionType::kNumberMap: return "number map";
    case OptionType::kStringMap: return "string map";
  }
  return "?";
}

namespace {

using Kind = OptionValue::Kind;

std::string Num(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof(buffer), "%g", v);
  return buffer;
}

// "an integer >= 1", "a number in [0, 1]", "a number > 0".
std::string RangeText(const OptionSpec& spec, bool integer) {
  std::string what = integer ? "an integer" : "a number";
  if (spec.min && spec.max)
    return what + " in " + (spec.min_exclusive ? "(" : "[") + Num(*spec.min) + ", " + Num(*spec.max) + "]";
  if (spec.min) return what + (spec.min_exclusive ? " > " : " >= ") + Num(*spec.min);
  if (spec.max) return what + " <= " + Num(*spec.max);
  return what;
}

Status CheckNumber(const OptionSpec& spec, const OptionValue& v, bool integer) {
  const bool type_ok = v.kind == Kind::kNumber && std::isfinite(v.number) && (!integer || v.is_integer);
  bool in_range = type_ok;
  if (type_ok && spec.min) in_range = spec.min_exclusive ? v.number > *spec.min : v.number >= *spec.min;
  if (in_range && spec.max) in_range = v.number <= *spec.max;
  if (in_range) return OkStatus();
  return InvalidArgument("expected " + RangeText(spec, integer) + ", got " + FormatOptionValue(v));
}

std::string ChoiceList(const std::vector<std::string>& choices) {
  std::string out;
  for (size_t i = 0; i < choices.size(); ++i) out += (i ? ", " : "") + choices[i];
  return out;
}

Status CheckString(const OptionSpec& spec, const OptionValue& v) {
  if (v.kind != Kind::kString) return InvalidArgument("expected a string, got " + FormatOptionValue(v));
  if (spec.type == OptionType::kPath) {
    if (v.text.empty()) return InvalidArgument("expected a path, got an empty string");
    return OkStatus();
  }
  if (spec.choices.empty()) return OkStatus();
  for (const std::string& choice : spec.choices)
    if (v.text == choice) return OkStatus();
  return InvalidArgument("expected one of " + ChoiceList(spec.choices) + ", got " + FormatOptionValue(v));
}

// Elements of lists and maps: numbers against the spec's range, or strings.
Status CheckElements(const OptionSpec& spec, const OptionValue& v, bool numbers) {
  for (size_t i = 0; i < v.items.size(); ++i) {
    // Built by appending: gcc 12 reports a false -Wrestrict on "[" + std::to_string(i).
    std::string where;
    if (v.kind == Kind::kObject) {
      where.append("\"").append(v.keys[i]).append("\"");
    } else {
      where.append("[").append(std::to_string(i)).append("]");
    }
    const OptionValue& item = v.items[i];
    if (numbers) {
      if (Status s = CheckNumber(spec, item, false); !s.ok()) return InvalidArgument(where + ": " + s.message());
    } else if (item.kind != Kind::kString) {
      return InvalidArgument(where + ": expected a string, got " + FormatOptionValue(item));
    }
  }
  return OkStatus();
}

Status CheckShape(const OptionSpec& spec, const OptionValue& v) {
  switch (spec.type) {
    case OptionType::kBool:
      if (v.kind != Kind::kBool) return InvalidArgument("expected true or false, got " + FormatOptionValue(v));
      return OkStatus();
    case OptionType::kInt: return CheckNumber(spec, v, true);
    case OptionType::kNumber: return CheckNumber(spec, v, false);
    case OptionType::kString:
    case OptionType::kPath: return CheckString(spec, v);
    case OptionType::kNumberList:
    case OptionType::kStringList:
      if (v.kind != Kind::kArray) return InvalidArgument("expected an array, got " + FormatOptionValue(v));
      return CheckElements(spec, v, spec.type == OptionType::kNumberList);
    case OptionType::kNumberMap:
    case OptionType::kStringMap:
      if (v.kind != Kind::kObject) return InvalidArgument("expected an object, got " + FormatOptionValue(v));
      return CheckElements(spec, v, spec.type == OptionType::kNumberMap);
  }
  return OkStatus();
}

}  // namespace

Status CheckOption(const OptionSpec& spec, const OptionValue& value) {
  RETURN_IF_ERROR(CheckShape(spec, value));
  if (spec.check) return spec.check(value);
  return OkStatus();
}

bool NodeOptions::Has(const std::string& name) const {
  const auto it = values_.find(name);
  return it != values_.end() && !it->second.is_null();
}

const OptionValue& NodeOptions::Get(const std::string& name) const {
  static const OptionValue kNull;
  const auto it = values_.find(name);
  return it == values_.end() ? kNull : it->second;
}

std::vector<double> NodeOptions::NumberList(const std::string& name) const {
  std::vector<double> out;
  for (const OptionValue& item : Get(name).items) out.push_back(item.number);
  return out;
}

std::vector<std::string> NodeOptions::StringList(const std::string& name) const {
  std::vector<std::string> out;
  for (const OptionValue& item : Get(name).items) out.push_back(item.text);
  return out;
}

std::map<std::string, double> NodeOptions::NumberMap(const std::string& name) const {
  std::map<std::string, double> out;
  const OptionValue& v = Get(name);
  for (size_t i = 0; i < v.items.size(); ++i) out[v.keys[i]] = v.items[i].number;
  return out;
}

std::map<std::string, std::string> NodeOptions::StringMap(const std::string& name) const {
  std::map<std::string, std::string> out;
  const OptionValue& v = Get(name);
  for (size_t i = 0; i < v.items.size(); ++i) out[v.keys[i]] = v.items[i].text;
  return out;
}

const Scene& NodeInputs::Motion(const std::string& port) const {
  return *std::get<std::shared_ptr<const Scene>>(values_.at(port));
}

const MotionDatabase& NodeInputs::Database(const std::string& port) const {
  return *std::get<std::shared_ptr<const MotionDatabase>>(values_.at(port));
}

const PcaModel& NodeInputs::Model(const std::string& port) const {
  return *std::get<std::shared_ptr<const PcaModel>>(values_.at(port));
}

}  // namespace mocapfill::graph
