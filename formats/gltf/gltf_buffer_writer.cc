#include "formats/gltf/tinygltf_private.h"

#include "formats/gltf/gltf_export_internal.h"

namespace mocapfill::gltf_internal {

int BufferWriter::AddView(const void* data, size_t size, int target) {
  bytes_.resize((bytes_.size() + 3) / 4 * 4, 0);  // zero padding to the next 4-byte boundary
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = base_ + bytes_.size();
  view.byteLength = size;
  view.target = target;
  const auto* p = static_cast<const unsigned char*>(data);
  bytes_.insert(bytes_.end(), p, p + size);
  model_.bufferViews.push_back(std::move(view));
  return static_cast<int>(model_.bufferViews.size()) - 1;
}

void BufferWriter::Reserve(size_t bytes) {
  bytes_.reserve(bytes_.size() + bytes + 3);
}

float* BufferWriter::AddFloatView(size_t count, int& view) {
  bytes_.resize((bytes_.size() + 3) / 4 * 4, 0);
  const size_t offset = bytes_.size();
  tinygltf::BufferView buffer_view;
  buffer_view.buffer = 0;
  buffer_view.byteOffset = base_ + offset;
  buffer_view.byteLength = count * sizeof(float);
  bytes_.resize(offset + count * sizeof(float));
  model_.bufferViews.push_back(std::move(buffer_view));
  view = static_cast<int>(model_.bufferViews.size()) - 1;
  return reinterpret_cast<float*>(bytes_.data() + offset);  // 4-byte aligned: offset % 4 == 0
}

int BufferWriter::AddViewAt(size_t byte_offset, size_t byte_length) {
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = byte_offset;
  view.byteLength = byte_length;
  model_.bufferViews.push_back(std::move(view));
  return static_cast<int>(model_.bufferViews.size()) - 1;
}

int BufferWriter::AddAccessor(int view, size_t byte_offset, int component_type, int type, size_t count,
                              const std::vector<double>& min, const std::vector<double>& max) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.byteOffset = byte_offset;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = count;
  accessor.minValues = min;
  accessor.maxValues = max;
  model_.accessors.push_back(std::move(accessor));
  return static_cast<int>(model_.accessors.size()) - 1;
}

void BufferWriter::Finish() {
  if (bytes_.empty()) return;
  bytes_.resize((bytes_.size() + 3) / 4 * 4, 0);
  tinygltf::Buffer buffer;
  buffer.data = std::move(bytes_);
  model_.buffers.push_back(std::move(buffer));
  bytes_.clear();
}

std::vector<unsigned char> BufferWriter::TakeBinaryChunk() {
  bytes_.resize((bytes_.size() + 3) / 4 * 4, 0);
  std::vector<unsigned char> bytes = std::move(bytes_);
  bytes_.clear();
  return bytes;
}

}  // namespace mocapfill::gltf_internal
