// Accessor reading with every bound checked before a byte is touched: tinygltf 2.7 does
// not verify that accessors fit their buffer views or views their buffers.
#include "formats/gltf/tinygltf_private.h"

#include <algorithm>
#include <cstring>

#include "formats/gltf/gltf_import_internal.h"

namespace mocapfill::gltf_internal {

namespace {

// Elements of an accessor without a buffer view are zeros we must allocate; cap them.
constexpr uint64_t kMaxZeroFilledValues = uint64_t{1} << 26;

double ReadComponent(const unsigned char* p, int component_type, bool normalized) {
  switch (component_type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      int8_t v;
      std::memcpy(&v, p, 1);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE: {
      uint8_t v;
      std::memcpy(&v, p, 1);
      return normalized ? v / 255.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0 : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return v;
    }
    default: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
  }
}

// Checks that bufferViews[view] lies inside its buffer; returns the view.
Result<const tinygltf::BufferView*> CheckedView(const tinygltf::Model& model, int view, const std::string& what) {
  if (view < 0 || static_cast<size_t>(view) >= model.bufferViews.size())
    return InvalidData(what + "buffer view " + Str(view) + " out of range (" + Str(model.bufferViews.size()) +
                       " buffer views)");
  const tinygltf::BufferView& v = model.bufferViews[view];
  const std::string field = "bufferViews[" + Str(view) + "]: ";
  if (v.buffer < 0 || static_cast<size_t>(v.buffer) >= model.buffers.size())
    return InvalidData(field + "buffer " + Str(v.buffer) + " out of range (" + Str(model.buffers.size()) + " buffers)");
  const size_t buffer_size = model.buffers[v.buffer].data.size();
  if (v.byteOffset > buffer_size || v.byteLength > buffer_size - v.byteOffset)
    return InvalidData(field + "bytes [" + Str(v.byteOffset) + ", " + Str(uint64_t{v.byteOffset} + v.byteLength) +
                       ") exceed buffers[" + Str(v.buffer) + "] (" + Str(buffer_size) + " bytes)");
  return &v;
}

// Checks that `count` elements of `element_size` bytes, `stride` apart, starting at
// `offset` fit in the view.
Status CheckFits(const tinygltf::BufferView& view, int view_index, uint64_t offset, uint64_t stride,
                 uint64_t element_size, uint64_t count, const std::string& what) {
  if (count > view.byteLength || offset > view.byteLength ||
      offset + stride * (count - 1) + element_size > view.byteLength)
    return InvalidData(what + Str(count) + " elements of " + Str(element_size) + " bytes (stride " + Str(stride) +
                       ") from offset " + Str(offset) + " exceed buffer view " + Str(view_index) + " (" +
                       Str(view.byteLength) + " bytes)");
  return OkStatus();
}

Status ApplySparse(const tinygltf::Model& model, const tinygltf::Accessor& a, int component_size,
                   AccessorData& data, const std::string& field) {
  const auto& sparse = a.sparse;
  if (sparse.count < 1 || static_cast<size_t>(sparse.count) > data.count)
    return InvalidData(field + "sparse.count " + Str(sparse.count) + " outside [1, " + Str(data.count) + "]");
  const int index_type = sparse.indices.componentType;
  const int index_size = index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE    ? 1
                         : index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT ? 2
                         : index_type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT   ? 4
                                                                                : 0;
  if (index_size == 0) return InvalidData(field + "sparse.indices.componentType " + Str(index_type) + " is not unsigned");
  ASSIGN_OR_RETURN(const tinygltf::BufferView* iv, CheckedView(model, sparse.indices.bufferView, field + "sparse.indices: "));
  ASSIGN_OR_RETURN(const tinygltf::BufferView* vv, CheckedView(model, sparse.values.bufferView, field + "sparse.values: "));
  const uint64_t n = static_cast<uint64_t>(sparse.count);
  const uint64_t element_size = uint64_t(component_size) * data.components;
  if (sparse.indices.byteOffset < 0 || sparse.values.byteOffset < 0)
    return InvalidData(field + "sparse byteOffset is negative");
  RETURN_IF_ERROR(CheckFits(*iv, sparse.indices.bufferView, sparse.indices.byteOffset, index_size, index_size, n,
                            field + "sparse.indices: "));
  RETURN_IF_ERROR(CheckFits(*vv, sparse.values.bufferView, sparse.values.byteOffset, element_size, element_size, n,
                            field + "sparse.values: "));
  const unsigned char* indices = model.buffers[iv->buffer].data.data() + iv->byteOffset + sparse.indices.byteOffset;
  const unsigned char* values = model.buffers[vv->buffer].data.data() + vv->byteOffset + sparse.values.byteOffset;
  double previous = -1;
  for (uint64_t i = 0; i < n; ++i) {
    const double index = ReadComponent(indices + i * index_size, index_type, false);
    if (index <= previous || index >= static_cast<double>(data.count))
      return InvalidData(field + "sparse index " + Str(static_cast<uint64_t>(index)) + " at position " + Str(i) +
                         " is out of range or not increasing");
    previous = index;
    for (int c = 0; c < data.components; ++c)
      data.values[static_cast<size_t>(index) * data.components + c] =
          ReadComponent(values + i * element_size + c * component_size, a.componentType, a.normalized);
  }
  return OkStatus();
}

}  // namespace

Result<AccessorData> ReadAccessor(const tinygltf::Model& model, int index) {
  if (index < 0 || static_cast<size_t>(index) >= model.accessors.size())
    return InvalidData("accessor " + Str(index) + " out of range (" + Str(model.accessors.size()) + " accessors)");
  const tinygltf::Accessor& a = model.accessors[index];
  const std::string field = "accessors[" + Str(index) + "]: ";
  const int component_size = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(a.componentType));
  const int components = tinygltf::GetNumComponentsInType(static_cast<uint32_t>(a.type));
  if (component_size <= 0 || a.componentType == TINYGLTF_COMPONENT_TYPE_INT ||
      a.componentType == TINYGLTF_COMPONENT_TYPE_DOUBLE)
    return InvalidData(field + "componentType " + Str(a.componentType) + " is not a glTF 2.0 component type");
  if (components <= 0) return InvalidData(field + "type is not SCALAR, VEC2-4 or MAT2-4");
  if ((a.type == TINYGLTF_TYPE_MAT2 || a.type == TINYGLTF_TYPE_MAT3) && component_size < 4)
    return Unsupported(field + "MAT2/MAT3 with 1- or 2-byte components (column padding) is not supported");
  if (a.count == 0) return InvalidData(field + "count is 0 (an accessor needs at least one element)");

  AccessorData data;
  data.count = a.count;
  data.components = components;
  data.component_type = a.componentType;
  data.normalized = a.normalized;
  const uint64_t element_size = uint64_t(component_size) * components;
  if (a.bufferView < 0) {
    if (uint64_t{a.count} * components > kMaxZeroFilledValues)
      return InvalidData(field + "count " + Str(a.count) + " is too large for an accessor without a buffer view");
    data.values.assign(a.count * components, 0.0);
  } else {
    ASSIGN_OR_RETURN(const tinygltf::BufferView* view, CheckedView(model, a.bufferView, field));
    const uint64_t stride = view->byteStride ? view->byteStride : element_size;
    if (stride < element_size)
      return InvalidData(field + "byteStride " + Str(stride) + " of buffer view " + Str(a.bufferView) +
                         " is smaller than an element (" + Str(element_size) + " bytes)");
    RETURN_IF_ERROR(CheckFits(*view, a.bufferView, a.byteOffset, stride, element_size, a.count, field));
    const unsigned char* base = model.buffers[view->buffer].data.data() + view->byteOffset + a.byteOffset;
    data.values.resize(a.count * components);
    for (size_t i = 0; i < a.count; ++i)
      for (int c = 0; c < components; ++c)
        data.values[i * components + c] = ReadComponent(base + i * stride + c * component_size, a.componentType, a.normalized);
  }
  if (a.sparse.isSparse) RETURN_IF_ERROR(ApplySparse(model, a, component_size, data, field));
  return data;
}

}  // namespace mocapfill::gltf_internal
