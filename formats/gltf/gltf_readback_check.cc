#include "formats/gltf/tinygltf_private.h"

#include "formats/gltf/gltf_readback_check.h"

#include <cmath>
#include <string>
#include <vector>

#include "formats/gltf/gltf_export_internal.h"
#include "formats/gltf/gltf_writer.h"

namespace mocapfill::gltf_internal {

namespace {

const char kDataUriHeader[] = "data:application/octet-stream;base64,";

// What the loader fills that is not in the JSON as such: the legacy parameter maps of a
// material (a copy of its factors), and a .gltf buffer's data URI (its bytes are in data).
void DropLoaderCopies(tinygltf::Model& read) {
  for (tinygltf::Material& m : read.materials) {
    m.values.clear();
    m.additionalValues.clear();
  }
  for (tinygltf::Buffer& b : read.buffers)
    if (b.uri.rfind(kDataUriHeader, 0) == 0) b.uri.clear();
}

// `value` as it reads back: the loader drops nulls and empty arrays and objects, and the
// writer prints as null what has nothing to print (an empty array or object, a NaN).
tinygltf::Value AsReadBack(const tinygltf::Value& value) {
  switch (value.Type()) {
    case tinygltf::ARRAY_TYPE: {
      tinygltf::Value::Array items;
      for (size_t i = 0; i < value.ArrayLen(); ++i) {
        tinygltf::Value item = AsReadBack(value.Get(static_cast<int>(i)));
        if (item.Type() != tinygltf::NULL_TYPE) items.push_back(std::move(item));
      }
      return items.empty() ? tinygltf::Value() : tinygltf::Value(std::move(items));
    }
    case tinygltf::OBJECT_TYPE: {
      tinygltf::Value::Object members;
      for (const auto& [key, member] : value.Get<tinygltf::Value::Object>()) {
        tinygltf::Value item = AsReadBack(member);
        if (item.Type() != tinygltf::NULL_TYPE) members.emplace(key, std::move(item));
      }
      return members.empty() ? tinygltf::Value() : tinygltf::Value(std::move(members));
    }
    case tinygltf::REAL_TYPE:
      return std::isfinite(value.Get<double>()) ? value : tinygltf::Value();
    case tinygltf::BINARY_TYPE:
      return tinygltf::Value();
    default:
      return value;
  }
}

template <class Item>
void ExtrasAsReadBack(std::vector<Item>& items) {
  for (Item& item : items) item.extras = AsReadBack(item.extras);
}

// The written model as the JSON says it: extras as they read back, and a new material's
// emissiveFactor, which is empty, as the default [0, 0, 0] the loader fills in for it.
void AsWritten(tinygltf::Model& m) {
  m.extras = AsReadBack(m.extras);
  m.asset.extras = AsReadBack(m.asset.extras);
  ExtrasAsReadBack(m.accessors);
  ExtrasAsReadBack(m.animations);
  ExtrasAsReadBack(m.bufferViews);
  ExtrasAsReadBack(m.buffers);
  ExtrasAsReadBack(m.materials);
  ExtrasAsReadBack(m.meshes);
  ExtrasAsReadBack(m.nodes);
  ExtrasAsReadBack(m.scenes);
  for (tinygltf::Material& material : m.materials)
    if (material.emissiveFactor.empty()) material.emissiveFactor = {0.0, 0.0, 0.0};
}

template <class Item>
std::string FirstDifference(const char* what, const std::vector<Item>& written, const std::vector<Item>& read) {
  if (written.size() != read.size())
    return std::string(what) + ": " + Str(written.size()) + " written, " + Str(read.size()) + " read";
  for (size_t i = 0; i < written.size(); ++i)
    if (!(written[i] == read[i])) return std::string(what) + "[" + Str(i) + "]";
  return "";
}

// tinygltf's operator== takes numbers within 1e-12 of each other as equal; the writer's
// shortest round-trip digits must give back the very same doubles.
bool SameExactly(const tinygltf::Value& a, const tinygltf::Value& b) {
  if (a.Type() != b.Type()) return false;
  if (a.Type() == tinygltf::REAL_TYPE) return a.Get<double>() == b.Get<double>();
  if (a.Type() == tinygltf::ARRAY_TYPE) {
    if (a.ArrayLen() != b.ArrayLen()) return false;
    for (size_t i = 0; i < a.ArrayLen(); ++i)
      if (!SameExactly(a.Get(static_cast<int>(i)), b.Get(static_cast<int>(i)))) return false;
    return true;
  }
  if (a.Type() == tinygltf::OBJECT_TYPE) {
    const tinygltf::Value::Object &x = a.Get<tinygltf::Value::Object>(), &y = b.Get<tinygltf::Value::Object>();
    if (x.size() != y.size()) return false;
    for (auto i = x.begin(), j = y.begin(); i != x.end(); ++i, ++j)
      if (i->first != j->first || !SameExactly(i->second, j->second)) return false;
    return true;
  }
  return a == b;
}

template <class Item, class Same>
std::string FirstInexact(const char* what, const std::vector<Item>& written, const std::vector<Item>& read, Same same) {
  for (size_t i = 0; i < written.size(); ++i)
    if (!SameExactly(written[i].extras, read[i].extras) || !same(written[i], read[i]))
      return std::string(what) + "[" + Str(i) + "]";
  return "";
}

std::string FirstInexactNumber(const tinygltf::Model& written, const tinygltf::Model& read) {
  const auto any = [](const auto&, const auto&) { return true; };
  for (const std::string& d :
       {FirstInexact("accessors", written.accessors, read.accessors,
                     [](const tinygltf::Accessor& a, const tinygltf::Accessor& b) {
                       return a.minValues == b.minValues && a.maxValues == b.maxValues;
                     }),
        FirstInexact("materials", written.materials, read.materials,
                     [](const tinygltf::Material& a, const tinygltf::Material& b) {
                       const tinygltf::PbrMetallicRoughness &x = a.pbrMetallicRoughness, &y = b.pbrMetallicRoughness;
                       return a.emissiveFactor == b.emissiveFactor && a.alphaCutoff == b.alphaCutoff &&
                              x.baseColorFactor == y.baseColorFactor && x.metallicFactor == y.metallicFactor &&
                              x.roughnessFactor == y.roughnessFactor;
                     }),
        FirstInexact("meshes", written.meshes, read.meshes,
                     [](const tinygltf::Mesh& a, const tinygltf::Mesh& b) { return a.weights == b.weights; }),
        FirstInexact("nodes", written.nodes, read.nodes,
                     [](const tinygltf::Node& a, const tinygltf::Node& b) {
                       return a.translation == b.translation && a.rotation == b.rotation && a.scale == b.scale &&
                              a.matrix == b.matrix && a.weights == b.weights;
                     }),
        FirstInexact("animations", written.animations, read.animations, any),
        FirstInexact("bufferViews", written.bufferViews, read.bufferViews, any),
        FirstInexact("buffers", written.buffers, read.buffers, any),
        FirstInexact("scenes", written.scenes, read.scenes, any)})
    if (!d.empty()) return d;
  if (!SameExactly(written.asset.extras, read.asset.extras)) return "asset";
  if (!SameExactly(written.extras, read.extras)) return "extras";
  return "";
}

std::string FirstDifference(const tinygltf::Model& written, const tinygltf::Model& read) {
  for (const std::string& d : {FirstDifference("accessors", written.accessors, read.accessors),
                               FirstDifference("animations", written.animations, read.animations),
                               FirstDifference("bufferViews", written.bufferViews, read.bufferViews),
                               FirstDifference("buffers", written.buffers, read.buffers),
                               FirstDifference("materials", written.materials, read.materials),
                               FirstDifference("meshes", written.meshes, read.meshes),
                               FirstDifference("nodes", written.nodes, read.nodes),
                               FirstDifference("scenes", written.scenes, read.scenes),
                               FirstDifference("skins", written.skins, read.skins)})
    if (!d.empty()) return d;
  if (!(written.asset == read.asset)) return "asset";
  if (written.defaultScene != read.defaultScene) return "scene";
  if (!(written == read)) return "the model";  // a member not listed above
  return FirstInexactNumber(written, read);
}

}  // namespace

Status CheckWrittenModelReadsBack(const Scene& scene, bool binary, const ExportOptions& options) {
  ASSIGN_OR_RETURN(const std::string bytes, WriteGltf(scene, binary, options));
  tinygltf::Model written;
  BufferWriter buffer(written);
  RETURN_IF_ERROR(BuildExportModel(scene, options, buffer, written));
  if (binary) {
    // The loader gives a .glb's binary chunk as buffers[0].
    tinygltf::Buffer chunk;
    chunk.data = buffer.TakeBinaryChunk();
    if (!chunk.data.empty()) written.buffers.push_back(std::move(chunk));
  } else {
    buffer.Finish();
  }
  tinygltf::TinyGLTF loader;
  tinygltf::Model read;
  std::string error, warning;
  const bool loaded =
      binary ? loader.LoadBinaryFromMemory(&read, &error, &warning, reinterpret_cast<const unsigned char*>(bytes.data()),
                                           static_cast<unsigned>(bytes.size()))
             : loader.LoadASCIIFromString(&read, &error, &warning, bytes.data(), static_cast<unsigned>(bytes.size()), "");
  if (!loaded) return Internal("tinygltf cannot read the written file: " + error);
  DropLoaderCopies(read);
  AsWritten(written);
  const std::string difference = FirstDifference(written, read);
  if (!difference.empty()) return Internal(difference + " reads back otherwise than written");
  return OkStatus();
}

}  // namespace mocapfill::gltf_internal
