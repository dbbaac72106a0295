// Internal to formats/gltf: the members of the glTF writer's objects (gltf_json_writer.cc),
// each printed as tinygltf 2.7's serialiser prints it, and tinygltf::Value as its ValueToJson
// prints one.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "formats/gltf/gltf_json_text.h"
#include "formats/gltf/tinygltf_name.h"

namespace tinygltf {
class Value;
}

namespace mocapfill::gltf_internal {

class GltfJsonMembers {
 public:
  explicit GltfJsonMembers(JsonText& json) : json_(json) {}

 protected:
  void IntMember(const char* key, int64_t v) {
    json_.Key(key);
    json_.Int(v);
  }
  void UnsignedMember(const char* key, uint64_t v) {
    json_.Key(key);
    json_.Unsigned(v);
  }
  void DoubleMember(const char* key, double v) {
    json_.Key(key);
    json_.Double(v);
  }
  void BoolMember(const char* key, bool v) {
    json_.Key(key);
    json_.Bool(v);
  }
  // A string property, which tinygltf passes on as c_str(): the text ends at a NUL.
  void PropertyMember(const char* key, const std::string& v);
  // Number arrays are left out when empty.
  void DoublesMember(const char* key, const std::vector<double>& values);
  void IntsMember(const char* key, const std::vector<int>& values);
  // An accessor's min or max: integers (truncated) unless the components are `real`.
  void BoundsMember(const char* key, const std::vector<double>& values, bool real);
  // Extras, when they print (Prints).
  void ExtrasMember(const tinygltf::Value& extras);

  // Whether a value prints at all: null and binary values are left out, members and
  // elements alike.
  static bool Prints(const tinygltf::Value& value);
  // An array or object with nothing that prints prints as null.
  void ValueText(const tinygltf::Value& value);

  JsonText& json_;
};

// Standard base64 with '=' padding, as tinygltf writes a buffer's data URI.
void AppendBase64(const std::vector<unsigned char>& bytes, std::string& out);

}  // namespace mocapfill::gltf_internal
