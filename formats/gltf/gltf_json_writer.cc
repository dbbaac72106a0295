// The JSON of an exported glTF model, with the members, defaults and layout of tinygltf 2.7's
// serialiser (SerializeGltfModel and its helpers in tiny_gltf.h), so that the bytes of a file
// do not depend on which of the two wrote it: a member at a default tinygltf leaves out is
// left out, keys come in sorted order (tinygltf's JSON objects are std::maps), and a string
// property ends at a NUL (tinygltf passes c_str()).
#include "formats/gltf/tinygltf_private.h"

#include <cmath>
#include <optional>
#include <string>

#include "formats/gltf/gltf_export_internal.h"
#include "formats/gltf/gltf_json_text.h"
#include "formats/gltf/gltf_json_members.h"

namespace mocapfill::gltf_internal {

namespace {

// tinygltf's TINYGLTF_DOUBLE_EQUAL, by which it decides that a factor is at its default.
bool NearlyEqual(double a, double b) { return std::fabs(b - a) < 1e-12; }
bool NearlyEqual(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (!NearlyEqual(a[i], b[i])) return false;
  return true;
}

const char* AccessorTypeName(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR: return "SCALAR";
    case TINYGLTF_TYPE_VEC2: return "VEC2";
    case TINYGLTF_TYPE_VEC3: return "VEC3";
    case TINYGLTF_TYPE_VEC4: return "VEC4";
    case TINYGLTF_TYPE_MAT2: return "MAT2";
    case TINYGLTF_TYPE_MAT3: return "MAT3";
    case TINYGLTF_TYPE_MAT4: return "MAT4";
    default: return "";
  }
}

class ModelJson : public GltfJsonMembers {
 public:
  using GltfJsonMembers::GltfJsonMembers;

  void WriteAccessor(const tinygltf::Accessor& a) {
    json_.BeginObject();
    if (a.bufferView >= 0) IntMember("bufferView", a.bufferView);
    // (Unsigned: tinygltf's int turns negative past 2 GiB.)
    if (a.byteOffset != 0) UnsignedMember("byteOffset", a.byteOffset);
    IntMember("componentType", a.componentType);
    UnsignedMember("count", a.count);
    ExtrasMember(a.extras);
    // Bounds of integer components print as integers (truncated), as the spec wants them.
    const bool real = a.componentType == TINYGLTF_COMPONENT_TYPE_FLOAT ||
                      a.componentType == TINYGLTF_COMPONENT_TYPE_DOUBLE;
    BoundsMember("max", a.maxValues, real);
    BoundsMember("min", a.minValues, real);
    if (!a.name.empty()) PropertyMember("name", a.name);
    if (a.normalized) BoolMember("normalized", true);
    PropertyMember("type", AccessorTypeName(a.type));
    json_.EndObject();
  }

  void WriteAnimation(const tinygltf::Animation& animation) {
    json_.BeginObject();
    json_.Key("channels");
    json_.BeginArray();
    for (const tinygltf::AnimationChannel& c : animation.channels) {
      json_.Element();
      json_.BeginObject();
      ExtrasMember(c.extras);
      IntMember("sampler", c.sampler);
      json_.Key("target");
      json_.BeginObject();
      IntMember("node", c.target_node);
      PropertyMember("path", c.target_path);
      json_.EndObject();
      json_.EndObject();
    }
    json_.EndArray();
    ExtrasMember(animation.extras);
    if (!animation.name.empty()) PropertyMember("name", animation.name);
    json_.Key("samplers");
    json_.BeginArray();
    for (const tinygltf::AnimationSampler& s : animation.samplers) {
      json_.Element();
      json_.BeginObject();
      ExtrasMember(s.extras);
      IntMember("input", s.input);
      PropertyMember("interpolation", s.interpolation);
      IntMember("output", s.output);
      json_.EndObject();
    }
    json_.EndArray();
    json_.EndObject();
  }

  void WriteAsset(const tinygltf::Asset& asset) {
    json_.BeginObject();
    if (!asset.copyright.empty()) PropertyMember("copyright", asset.copyright);
    // Extras only as an object with members (tinygltf asks for its keys).
    if (!asset.extras.Keys().empty()) ExtrasMember(asset.extras);
    if (!asset.generator.empty()) PropertyMember("generator", asset.generator);
    PropertyMember("version", asset.version.empty() ? std::string("2.0") : asset.version);
    json_.EndObject();
  }

  void WriteBufferView(const tinygltf::BufferView& v) {
    json_.BeginObject();
    IntMember("buffer", v.buffer);
    UnsignedMember("byteLength", v.byteLength);
    if (v.byteOffset > 0) UnsignedMember("byteOffset", v.byteOffset);
    if (v.byteStride >= 4) UnsignedMember("byteStride", v.byteStride);
    ExtrasMember(v.extras);
    if (!v.name.empty()) PropertyMember("name", v.name);
    if (v.target == TINYGLTF_TARGET_ARRAY_BUFFER || v.target == TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER)
      IntMember("target", v.target);
    json_.EndObject();
  }

  // A .gltf buffer: its bytes as a base64 data URI.
  void WriteEmbeddedBuffer(const tinygltf::Buffer& buffer) {
    json_.BeginObject();
    UnsignedMember("byteLength", buffer.data.size());
    ExtrasMember(buffer.extras);
    if (!buffer.name.empty()) PropertyMember("name", buffer.name);
    json_.Key("uri");
    std::string& out = json_.RawStringStart();
    out += "data:application/octet-stream;base64,";
    AppendBase64(buffer.data, out);
    json_.RawStringEnd();
    json_.EndObject();
  }

  // A material with every member at its default prints as {} (null is not a material).
  void WriteMaterial(const tinygltf::Material& m) {
    json_.BeginObject();
    if (!NearlyEqual(m.alphaCutoff, 0.5)) DoubleMember("alphaCutoff", m.alphaCutoff);
    if (m.alphaMode != "OPAQUE") PropertyMember("alphaMode", m.alphaMode);
    if (m.doubleSided) BoolMember("doubleSided", true);
    if (!NearlyEqual(m.emissiveFactor, {0.0, 0.0, 0.0})) DoublesMember("emissiveFactor", m.emissiveFactor);
    ExtrasMember(m.extras);
    if (!m.name.empty()) PropertyMember("name", m.name);
    const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;
    const bool base_color = !NearlyEqual(pbr.baseColorFactor, {1.0, 1.0, 1.0, 1.0}) && !pbr.baseColorFactor.empty();
    const bool metallic = !NearlyEqual(pbr.metallicFactor, 1.0), roughness = !NearlyEqual(pbr.roughnessFactor, 1.0);
    // Left out when every member is at its default: readers refuse a null one.
    if (base_color || metallic || roughness || Prints(pbr.extras)) {
      json_.Key("pbrMetallicRoughness");
      json_.BeginObject();
      if (base_color) DoublesMember("baseColorFactor", pbr.baseColorFactor);
      ExtrasMember(pbr.extras);
      if (metallic) DoubleMember("metallicFactor", pbr.metallicFactor);
      if (roughness) DoubleMember("roughnessFactor", pbr.roughnessFactor);
      json_.EndObject();
    }
    json_.EndObjectOrEmpty();
  }

  void WriteMesh(const tinygltf::Mesh& mesh) {
    json_.BeginObject();
    ExtrasMember(mesh.extras);
    if (!mesh.name.empty()) PropertyMember("name", mesh.name);
    json_.Key("primitives");
    json_.BeginArray();
    for (const tinygltf::Primitive& p : mesh.primitives) {
      json_.Element();
      json_.BeginObject();
      json_.Key("attributes");
      json_.BeginObject();
      for (const auto& [name, accessor] : p.attributes) {
        json_.EscapedKey(std::string(name.c_str()));
        json_.Int(accessor);
      }
      json_.EndObject();
      ExtrasMember(p.extras);
      if (p.indices > -1) IntMember("indices", p.indices);
      if (p.material > -1) IntMember("material", p.material);
      IntMember("mode", p.mode);
      json_.EndObject();
    }
    json_.EndArray();
    DoublesMember("weights", mesh.weights);
    json_.EndObject();
  }

  void WriteNode(const tinygltf::Node& n) {
    json_.BeginObject();
    if (n.camera != -1) IntMember("camera", n.camera);
    IntsMember("children", n.children);
    ExtrasMember(n.extras);
    DoublesMember("matrix", n.matrix);
    if (n.mesh != -1) IntMember("mesh", n.mesh);
    if (!n.name.empty()) PropertyMember("name", n.name);
    DoublesMember("rotation", n.rotation);
    DoublesMember("scale", n.scale);
    if (n.skin != -1) IntMember("skin", n.skin);
    DoublesMember("translation", n.translation);
    DoublesMember("weights", n.weights);
    json_.EndObject();
  }

  void WriteScene(const tinygltf::Scene& s) {
    json_.BeginObject();
    ExtrasMember(s.extras);
    if (!s.name.empty()) PropertyMember("name", s.name);
    IntsMember("nodes", s.nodes);
    json_.EndObject();
  }

  // (tinygltf 2.7 writes no extras of a skin.)
  void WriteSkin(const tinygltf::Skin& skin) {
    json_.BeginObject();
    if (skin.inverseBindMatrices >= 0) IntMember("inverseBindMatrices", skin.inverseBindMatrices);
    IntsMember("joints", skin.joints);
    if (!skin.name.empty()) PropertyMember("name", skin.name);
    if (skin.skeleton >= 0) IntMember("skeleton", skin.skeleton);
    json_.EndObject();
  }

  template <class Item, class Write>
  void ArrayMember(const char* key, const std::vector<Item>& items, Write write) {
    if (items.empty()) return;
    json_.Key(key);
    json_.BeginArray();
    for (const Item& item : items) {
      json_.Element();
      (this->*write)(item);
    }
    json_.EndArray();
  }

  // The whole model. `glb_bin_bytes`: for a .glb, the size of its binary chunk, written as
  // buffers[0] (none when 0; the model holds no buffers); without it, the model's buffers,
  // embedded.
  void WriteModel(const tinygltf::Model& model, std::optional<size_t> glb_bin_bytes) {
    json_.BeginObject();
    ArrayMember("accessors", model.accessors, &ModelJson::WriteAccessor);
    if (!model.animations.empty()) {
      // Animations without channels are left out (and an array left empty prints as null).
      json_.Key("animations");
      json_.BeginArray();
      for (const tinygltf::Animation& animation : model.animations) {
        if (animation.channels.empty()) continue;
        json_.Element();
        WriteAnimation(animation);
      }
      json_.EndArray();
    }
    json_.Key("asset");
    WriteAsset(model.asset);
    ArrayMember("bufferViews", model.bufferViews, &ModelJson::WriteBufferView);
    if (!glb_bin_bytes) {
      ArrayMember("buffers", model.buffers, &ModelJson::WriteEmbeddedBuffer);
    } else if (*glb_bin_bytes > 0) {
      json_.Key("buffers");
      json_.BeginArray();
      json_.Element();
      json_.BeginObject();
      UnsignedMember("byteLength", *glb_bin_bytes);
      json_.EndObject();
      json_.EndArray();
    }
    ExtrasMember(model.extras);
    ArrayMember("materials", model.materials, &ModelJson::WriteMaterial);
    ArrayMember("meshes", model.meshes, &ModelJson::WriteMesh);
    ArrayMember("nodes", model.nodes, &ModelJson::WriteNode);
    if (model.defaultScene > -1) IntMember("scene", model.defaultScene);
    ArrayMember("scenes", model.scenes, &ModelJson::WriteScene);
    ArrayMember("skins", model.skins, &ModelJson::WriteSkin);
    json_.EndObject();
  }
};

// The members written above are those an export fills; a model with any other (which only
// a change to the exporter could bring) is refused rather than written without it.
Status CheckWritable(const tinygltf::Model& m) {
  const auto refuse = [](const char* what) { return Internal(std::string("the glTF writer does not write ") + what); };
  if (!m.textures.empty() || !m.images.empty() || !m.samplers.empty()) return refuse("textures");
  if (!m.cameras.empty() || !m.lights.empty()) return refuse("cameras or lights");
  if (!m.extensions.empty() || !m.extensionsUsed.empty() || !m.extensionsRequired.empty() ||
      !m.asset.extensions.empty())
    return refuse("extensions");
  for (const tinygltf::Accessor& a : m.accessors)
    if (a.sparse.isSparse) return refuse("sparse accessors");
  for (const tinygltf::Animation& a : m.animations) {
    if (!a.extensions.empty()) return refuse("extensions");
    for (const tinygltf::AnimationChannel& c : a.channels)
      if (!c.extensions.empty() || !c.target_extensions.empty()) return refuse("extensions");
  }
  for (const tinygltf::Material& mat : m.materials) {
    const tinygltf::PbrMetallicRoughness& pbr = mat.pbrMetallicRoughness;
    if (mat.normalTexture.index > -1 || mat.occlusionTexture.index > -1 || mat.emissiveTexture.index > -1 ||
        pbr.baseColorTexture.index > -1 || pbr.metallicRoughnessTexture.index > -1)
      return refuse("textures");
    if (!mat.extensions.empty() || !pbr.extensions.empty()) return refuse("extensions");
  }
  for (const tinygltf::Mesh& mesh : m.meshes) {
    if (!mesh.extensions.empty()) return refuse("extensions");
    for (const tinygltf::Primitive& p : mesh.primitives) {
      if (!p.targets.empty()) return refuse("morph targets");
      if (!p.extensions.empty()) return refuse("extensions");
    }
  }
  for (const tinygltf::Node& n : m.nodes)
    if (!n.extensions.empty()) return refuse("extensions");
  for (const tinygltf::Scene& s : m.scenes)
    if (!s.extensions.empty()) return refuse("extensions");
  return OkStatus();
}

}  // namespace

Result<std::string> GlbJson(const tinygltf::Model& model, size_t bin_bytes) {
  if (!model.buffers.empty()) return Internal("a .glb model's bytes are its binary chunk, not buffers");
  RETURN_IF_ERROR(CheckWritable(model));
  std::string out;
  out.reserve(512 + 160 * (model.accessors.size() + model.nodes.size()));
  JsonText json(out, -1);
  ModelJson(json).WriteModel(model, bin_bytes);
  return out;
}

Result<std::string> GltfJson(const tinygltf::Model& model, bool pretty) {
  RETURN_IF_ERROR(CheckWritable(model));
  size_t base64_bytes = 0;
  for (const tinygltf::Buffer& b : model.buffers) base64_bytes += (b.data.size() + 2) / 3 * 4;
  std::string out;
  out.reserve(1024 + base64_bytes + (pretty ? 400 : 160) * (model.accessors.size() + model.nodes.size()));
  JsonText json(out, pretty ? 2 : -1);
  ModelJson(json).WriteModel(model, std::nullopt);
  out += '\n';  // tinygltf ends a .gltf's text with std::endl
  return out;
}

}  // namespace mocapfill::gltf_internal
