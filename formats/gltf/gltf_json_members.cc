#include "formats/gltf/tinygltf_private.h"

#include "formats/gltf/gltf_json_members.h"

namespace mocapfill::gltf_internal {

void GltfJsonMembers::PropertyMember(const char* key, const std::string& v) {
  json_.Key(key);
  if (v.find('\0') == std::string::npos) {
    json_.String(v);
  } else {
    json_.String(std::string(v.c_str()));
  }
}

void GltfJsonMembers::DoublesMember(const char* key, const std::vector<double>& values) {
  if (values.empty()) return;
  json_.Key(key);
  json_.BeginArray();
  for (const double v : values) {
    json_.Element();
    json_.Double(v);
  }
  json_.EndArray();
}

void GltfJsonMembers::IntsMember(const char* key, const std::vector<int>& values) {
  if (values.empty()) return;
  json_.Key(key);
  json_.BeginArray();
  for (const int v : values) {
    json_.Element();
    json_.Int(v);
  }
  json_.EndArray();
}

void GltfJsonMembers::BoundsMember(const char* key, const std::vector<double>& values, bool real) {
  if (values.empty()) return;
  json_.Key(key);
  json_.BeginArray();
  for (const double v : values) {
    json_.Element();
    if (real) {
      json_.Double(v);
    } else {
      json_.Int(static_cast<int>(v));
    }
  }
  json_.EndArray();
}

void GltfJsonMembers::ExtrasMember(const tinygltf::Value& extras) {
  if (!Prints(extras)) return;
  json_.Key("extras");
  ValueText(extras);
}

bool GltfJsonMembers::Prints(const tinygltf::Value& value) {
  return value.Type() != tinygltf::NULL_TYPE && value.Type() != tinygltf::BINARY_TYPE;
}

void GltfJsonMembers::ValueText(const tinygltf::Value& value) {
  switch (value.Type()) {
    case tinygltf::REAL_TYPE:
      json_.Double(value.Get<double>());
      return;
    case tinygltf::INT_TYPE:
      json_.Int(value.Get<int>());
      return;
    case tinygltf::BOOL_TYPE:
      json_.Bool(value.Get<bool>());
      return;
    case tinygltf::STRING_TYPE:
      json_.String(value.Get<std::string>());
      return;
    case tinygltf::ARRAY_TYPE:
      json_.BeginArray();
      for (size_t i = 0; i < value.ArrayLen(); ++i) {
        const tinygltf::Value& element = value.Get(static_cast<int>(i));
        if (!Prints(element)) continue;
        json_.Element();
        ValueText(element);
      }
      json_.EndArray();
      return;
    case tinygltf::OBJECT_TYPE:
      json_.BeginObject();
      for (const auto& [key, member] : value.Get<tinygltf::Value::Object>()) {
        if (!Prints(member)) continue;
        json_.EscapedKey(key);
        ValueText(member);
      }
      json_.EndObject();
      return;
    default:
      json_.Null();  // not reached: callers ask Prints first
  }
}

void AppendBase64(const std::vector<unsigned char>& bytes, std::string& out) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  const size_t whole = bytes.size() / 3 * 3;
  const size_t start = out.size();
  out.resize(start + (bytes.size() + 2) / 3 * 4);
  char* p = out.data() + start;
  for (size_t i = 0; i < whole; i += 3) {
    const uint32_t v = (uint32_t{bytes[i]} << 16) | (uint32_t{bytes[i + 1]} << 8) | bytes[i + 2];
    *p++ = kDigits[v >> 18];
    *p++ = kDigits[(v >> 12) & 63];
    *p++ = kDigits[(v >> 6) & 63];
    *p++ = kDigits[v & 63];
  }
  if (whole < bytes.size()) {
    const bool two = whole + 1 < bytes.size();
    const uint32_t v = (uint32_t{bytes[whole]} << 16) | (two ? uint32_t{bytes[whole + 1]} << 8 : 0);
    *p++ = kDigits[v >> 18];
    *p++ = kDigits[(v >> 12) & 63];
    *p++ = two ? kDigits[(v >> 6) & 63] : '=';
    *p++ = '=';
  }
}

}  // namespace mocapfill::gltf_internal
