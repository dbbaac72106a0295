// The JSON chunk of a skeleton-and-animation .glb (a skin over the joints included), written straight from the tinygltf
// model instead of through tinygltf's serialiser. That serialiser builds an nlohmann::json
// tree (a std::map per object, a heap string per key) and then prints it: about 0.2 ms for
// a 22-joint clip, a tenth of a whole BVH conversion in batch mode. The text here is the
// same, byte for byte (tests compare the two over every corpus file): objects with their
// keys in std::map order, only the members tinygltf writes, and every number and string
// printed by nlohmann::json itself, so formatting and escaping cannot differ.
#include "formats/gltf/tinygltf_private.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <optional>
#include <string>

#include "formats/gltf/gltf_export_internal.h"

namespace mocapfill::gltf_internal {

namespace {

using tinygltf::Value;

// nlohmann's own formatting of a double (its serializer's dump_float): Grisu2 shortest
// round-trip digits, "null" for NaN and infinities. Called directly, not through a json
// value and a serializer (a locale lookup and allocations per number).
void AppendDouble(double v, std::string& out) {
  if (!std::isfinite(v)) {
    out += "null";
    return;
  }
  char digits[64];
  const char* end = nlohmann::detail::to_chars(digits, digits + sizeof(digits), v);
  out.append(digits, static_cast<size_t>(end - digits));
}
// Printable ASCII other than '"' and '\\' is written as it is, as nlohmann writes it; anything
// else (escapes, UTF-8 to validate) goes through nlohmann.
void AppendString(const std::string& s, std::string& out) {
  for (const char c : s)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7F || c == '"' || c == '\\') {
      out += nlohmann::json(s).dump();
      return;
    }
  out += '"';
  out += s;
  out += '"';
}
// A string property: tinygltf passes these through c_str(), so the text ends at a NUL.
void AppendProperty(const std::string& s, std::string& out) { AppendString(std::string(s.c_str()), out); }
template <class Integer>
void AppendInteger(Integer v, std::string& out) {
  out += std::to_string(v);
}

// Writes members of one object in the order they are added, which callers keep sorted.
class ObjectWriter {
 public:
  explicit ObjectWriter(std::string& out) : out_(out) { out_ += '{'; }
  ~ObjectWriter() { out_ += '}'; }
  std::string& Key(const char* key) {
    if (!first_) out_ += ',';
    first_ = false;
    out_ += '"';
    out_ += key;
    out_ += "\":";
    return out_;
  }

 private:
  std::string& out_;
  bool first_ = true;
};

template <class Number>
void AppendNumberArray(const std::vector<Number>& values, std::string& out) {
  out += '[';
  for (size_t i = 0; i < values.size(); ++i) {
    if (i > 0) out += ',';
    if constexpr (std::is_floating_point_v<Number>) {
      AppendDouble(values[i], out);
    } else {
      AppendInteger(values[i], out);
    }
  }
  out += ']';
}

// tinygltf's ValueToJson (nlohmann backend): false for null and binary values, which are
// left out; arrays and objects with nothing to hold print as null.
bool AppendValue(const Value& value, std::string& out) {
  switch (value.Type()) {
    case tinygltf::REAL_TYPE:
      AppendDouble(value.Get<double>(), out);
      return true;
    case tinygltf::INT_TYPE:
      AppendInteger(value.Get<int>(), out);
      return true;
    case tinygltf::BOOL_TYPE:
      out += value.Get<bool>() ? "true" : "false";
      return true;
    case tinygltf::STRING_TYPE:
      AppendString(value.Get<std::string>(), out);
      return true;
    case tinygltf::ARRAY_TYPE: {
      std::string items;
      for (size_t i = 0; i < value.ArrayLen(); ++i) {
        std::string item;
        if (!AppendValue(value.Get(static_cast<int>(i)), item)) continue;
        items += items.empty() ? "[" : ",";
        items += item;
      }
      out += items.empty() ? "null" : items + "]";
      return true;
    }
    case tinygltf::OBJECT_TYPE: {
      std::string members;
      for (const auto& [key, member] : value.Get<Value::Object>()) {
        std::string item;
        if (!AppendValue(member, item)) continue;
        members += members.empty() ? "{" : ",";
        AppendString(key, members);
        members += ':';
        members += item;
      }
      out += members.empty() ? "null" : members + "}";
      return true;
    }
    default:
      return false;
  }
}

bool IsNull(const Value& value) { return value.Type() == tinygltf::NULL_TYPE; }

// The parts of a model written here; anything else goes through tinygltf's serialiser.
bool IsSkeletonAndAnimation(const tinygltf::Model& m) {
  if (!m.buffers.empty() || !m.materials.empty() || !m.meshes.empty() || !m.textures.empty() || !m.images.empty() ||
      !m.samplers.empty() || !m.cameras.empty() || !m.lights.empty() || !m.extensionsUsed.empty() ||
      !m.extensionsRequired.empty() || !m.extensions.empty() || !IsNull(m.extras) || !m.asset.extensions.empty())
    return false;
  for (const tinygltf::Accessor& a : m.accessors)
    if (a.sparse.isSparse || a.normalized || !a.name.empty() || !IsNull(a.extras) ||
        a.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT || a.type < TINYGLTF_TYPE_VEC2 ||
        (a.type > TINYGLTF_TYPE_VEC4 && a.type != TINYGLTF_TYPE_SCALAR && a.type != TINYGLTF_TYPE_MAT4))
      return false;
  // (tinygltf 2.7 writes a skin's joints, inverseBindMatrices, skeleton and name only.)
  for (const tinygltf::Skin& skin : m.skins)
    if (skin.joints.empty()) return false;
  for (const tinygltf::Animation& animation : m.animations) {
    if (!animation.extensions.empty() || !IsNull(animation.extras) || animation.channels.empty() ||
        animation.samplers.empty())
      return false;
    for (const tinygltf::AnimationChannel& c : animation.channels)
      if (!IsNull(c.extras) || !c.extensions.empty() || !c.target_extensions.empty()) return false;
    for (const tinygltf::AnimationSampler& s : animation.samplers)
      if (!IsNull(s.extras)) return false;
  }
  for (const tinygltf::BufferView& v : m.bufferViews)
    if (!IsNull(v.extras) || !v.name.empty()) return false;
  // (tinygltf prints an object with no members as null; here such nodes and scenes are
  // left to it.)
  for (const tinygltf::Node& n : m.nodes)
    if (!n.matrix.empty() || n.mesh != -1 || n.skin != -1 || n.camera != -1 || !n.weights.empty() ||
        !n.extensions.empty() || n.name.empty())
      return false;
  for (const tinygltf::Scene& s : m.scenes)
    if (!s.extensions.empty() || !IsNull(s.extras) || !s.name.empty() || s.nodes.empty()) return false;
  return true;
}

const char* TypeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "SCALAR";
  }
}

void AppendAccessor(const tinygltf::Accessor& a, std::string& out) {
  ObjectWriter o(out);
  if (a.bufferView >= 0) AppendInteger(a.bufferView, o.Key("bufferView"));
  if (a.byteOffset != 0) AppendInteger(static_cast<int>(a.byteOffset), o.Key("byteOffset"));
  AppendInteger(a.componentType, o.Key("componentType"));
  AppendInteger(a.count, o.Key("count"));
  if (!a.maxValues.empty()) AppendNumberArray(a.maxValues, o.Key("max"));
  if (!a.minValues.empty()) AppendNumberArray(a.minValues, o.Key("min"));
  AppendProperty(TypeName(a.type), o.Key("type"));
}

void AppendAnimation(const tinygltf::Animation& animation, std::string& out) {
  ObjectWriter o(out);
  std::string& channels = o.Key("channels");
  channels += '[';
  for (size_t i = 0; i < animation.channels.size(); ++i) {
    const tinygltf::AnimationChannel& c = animation.channels[i];
    if (i > 0) channels += ',';
    ObjectWriter channel(channels);
    AppendInteger(c.sampler, channel.Key("sampler"));
    ObjectWriter target(channel.Key("target"));
    AppendInteger(c.target_node, target.Key("node"));
    AppendProperty(c.target_path, target.Key("path"));
  }
  channels += ']';
  if (!animation.name.empty()) AppendProperty(animation.name, o.Key("name"));
  std::string& samplers = o.Key("samplers");
  samplers += '[';
  for (size_t i = 0; i < animation.samplers.size(); ++i) {
    const tinygltf::AnimationSampler& s = animation.samplers[i];
    if (i > 0) samplers += ',';
    ObjectWriter sampler(samplers);
    AppendInteger(s.input, sampler.Key("input"));
    AppendProperty(s.interpolation, sampler.Key("interpolation"));
    AppendInteger(s.output, sampler.Key("output"));
  }
  samplers += ']';
}

void AppendAsset(const tinygltf::Asset& asset, std::string& out) {
  ObjectWriter o(out);
  if (!asset.copyright.empty()) AppendProperty(asset.copyright, o.Key("copyright"));
  if (!asset.extras.Keys().empty()) AppendValue(asset.extras, o.Key("extras"));
  if (!asset.generator.empty()) AppendProperty(asset.generator, o.Key("generator"));
  AppendProperty(asset.version.empty() ? std::string("2.0") : asset.version, o.Key("version"));
}

void AppendBufferView(const tinygltf::BufferView& v, std::string& out) {
  ObjectWriter o(out);
  AppendInteger(v.buffer, o.Key("buffer"));
  AppendInteger(v.byteLength, o.Key("byteLength"));
  if (v.byteOffset > 0) AppendInteger(v.byteOffset, o.Key("byteOffset"));
  if (v.byteStride >= 4) AppendInteger(v.byteStride, o.Key("byteStride"));
  if (v.target == TINYGLTF_TARGET_ARRAY_BUFFER || v.target == TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER)
    AppendInteger(v.target, o.Key("target"));
}

void AppendNode(const tinygltf::Node& n, std::string& out) {
  ObjectWriter o(out);
  if (!n.children.empty()) AppendNumberArray(n.children, o.Key("children"));
  if (!IsNull(n.extras)) {
    // A member only when the value prints (tinygltf's SerializeValue).
    std::string extras;
    if (AppendValue(n.extras, extras)) o.Key("extras") += extras;
  }
  if (!n.name.empty()) AppendProperty(n.name, o.Key("name"));
  if (!n.rotation.empty()) AppendNumberArray(n.rotation, o.Key("rotation"));
  if (!n.scale.empty()) AppendNumberArray(n.scale, o.Key("scale"));
  if (!n.translation.empty()) AppendNumberArray(n.translation, o.Key("translation"));
}

template <class Item, class Append>
void AppendArray(const std::vector<Item>& items, Append append, std::string& out) {
  out += '[';
  for (size_t i = 0; i < items.size(); ++i) {
    if (i > 0) out += ',';
    append(items[i], out);
  }
  out += ']';
}

}  // namespace

std::optional<std::string> SkeletonGlbJson(const tinygltf::Model& model, size_t bin_bytes) {
  if (!IsSkeletonAndAnimation(model)) return std::nullopt;
  std::string out;
  out.reserve(512 + 160 * (model.accessors.size() + model.nodes.size()));
  try {
    ObjectWriter o(out);
    if (!model.accessors.empty()) AppendArray(model.accessors, AppendAccessor, o.Key("accessors"));
    if (!model.animations.empty()) AppendArray(model.animations, AppendAnimation, o.Key("animations"));
    AppendAsset(model.asset, o.Key("asset"));
    if (!model.bufferViews.empty()) AppendArray(model.bufferViews, AppendBufferView, o.Key("bufferViews"));
    if (bin_bytes > 0) {
      std::string& buffers = o.Key("buffers");
      buffers += "[{\"byteLength\":";
      AppendInteger(bin_bytes, buffers);
      buffers += "}]";
    }
    if (!model.nodes.empty()) AppendArray(model.nodes, AppendNode, o.Key("nodes"));
    if (model.defaultScene > -1) AppendInteger(model.defaultScene, o.Key("scene"));
    if (!model.scenes.empty())
      AppendArray(
          model.scenes,
          [](const tinygltf::Scene& s, std::string& text) {
            ObjectWriter scene(text);
            if (!s.nodes.empty()) AppendNumberArray(s.nodes, scene.Key("nodes"));
          },
          o.Key("scenes"));
    if (!model.skins.empty())
      AppendArray(
          model.skins,
          [](const tinygltf::Skin& skin, std::string& text) {
            ObjectWriter s(text);
            if (skin.inverseBindMatrices >= 0) AppendInteger(skin.inverseBindMatrices, s.Key("inverseBindMatrices"));
            AppendNumberArray(skin.joints, s.Key("joints"));
            if (!skin.name.empty()) AppendProperty(skin.name, s.Key("name"));
            if (skin.skeleton >= 0) AppendInteger(skin.skeleton, s.Key("skeleton"));
          },
          o.Key("skins"));
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;  // a string that is not UTF-8: tinygltf's serialiser reports it
  }
  return out;
}

}  // namespace mocapfill::gltf_internal
