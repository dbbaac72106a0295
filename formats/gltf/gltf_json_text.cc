#include "formats/gltf/gltf_json_text.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace mocapfill::gltf_internal {

// nlohmann's serializer prints a double this way (dump_float); called directly, not through
// a json value and a serializer, which look up the locale and allocate for every number.
void JsonText::Double(double v) {
  if (!std::isfinite(v)) {
    out_ += "null";
    return;
  }
  char digits[64];
  const char* end = nlohmann::detail::to_chars(digits, digits + sizeof(digits), v);
  out_.append(digits, static_cast<size_t>(end - digits));
}

// Printable ASCII other than '"' and '\\' is written as it is, as nlohmann writes it;
// anything else (escapes, UTF-8 to validate) goes through nlohmann.
void JsonText::String(const std::string& s) {
  for (const char c : s)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7F || c == '"' || c == '\\') {
      out_ += nlohmann::json(s).dump();
      return;
    }
  out_ += '"';
  out_ += s;
  out_ += '"';
}

void JsonText::EscapedKey(const std::string& key) {
  Separator('{');
  String(key);
  out_ += indent_ < 0 ? ":" : ": ";
}

}  // namespace mocapfill::gltf_internal
