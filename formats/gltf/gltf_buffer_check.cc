#include "formats/gltf/gltf_buffer_check.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <filesystem>

namespace mocapfill::gltf_internal {

namespace {

using nlohmann::json;

// Media types tinygltf decodes for buffers.
constexpr std::string_view kBufferMediaTypes[] = {"application/octet-stream", "application/gltf-buffer"};

// Decoded size of base64 text (ignoring '=' padding), or nullopt if it is not base64.
std::optional<size_t> Base64DecodedSize(std::string_view text) {
  size_t symbols = 0;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (c == '=') {
      if (text.substr(i).find_first_not_of('=') != std::string_view::npos) return std::nullopt;
      break;
    }
    if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '+' || c == '/')) return std::nullopt;
    ++symbols;
  }
  return symbols * 3 / 4;
}

// %XX decoding of relative URIs, as tinygltf does before opening the file.
std::string PercentDecode(std::string_view uri) {
  std::string out;
  for (size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size() && std::isxdigit(static_cast<unsigned char>(uri[i + 1])) &&
        std::isxdigit(static_cast<unsigned char>(uri[i + 2]))) {
      out += static_cast<char>(std::stoi(std::string(uri.substr(i + 1, 2)), nullptr, 16));
      i += 2;
    } else {
      out += uri[i];
    }
  }
  return out;
}

Status CheckDataUri(const std::string& field, std::string_view uri, size_t byte_length) {
  const size_t comma = uri.find(',');
  const std::string_view header = uri.substr(5, comma == std::string_view::npos ? 0 : comma - 5);
  if (comma == std::string_view::npos || header.size() < 7 || header.substr(header.size() - 7) != ";base64")
    return InvalidData(field + ": data URI is not base64-encoded");
  const std::string_view media = header.substr(0, header.size() - 7);
  bool known = false;
  for (std::string_view m : kBufferMediaTypes) known = known || media == m;
  if (!known)
    return InvalidData(field + ": data URI media type '" + std::string(media) +
                       "', expected application/octet-stream or application/gltf-buffer");
  const auto decoded = Base64DecodedSize(uri.substr(comma + 1));
  if (!decoded) return InvalidData(field + ": data URI holds invalid base64 text");
  if (*decoded != byte_length)
    return InvalidData(field + ": byteLength " + std::to_string(byte_length) + " but the data URI holds " +
                       std::to_string(*decoded) + " bytes");
  return OkStatus();
}

Status CheckExternalFile(const std::string& field, const std::string& uri, const std::string& base_dir,
                         size_t byte_length) {
  if (uri.find("://") != std::string::npos || (!uri.empty() && uri[0] == '/'))
    return InvalidData(field + ": uri '" + uri + "' is not a relative file path or a data URI");
  const std::filesystem::path file = std::filesystem::path(base_dir) / PercentDecode(uri);
  std::error_code ec;
  const auto size = std::filesystem::file_size(file, ec);
  if (ec) return InvalidData(field + ": cannot read '" + uri + "' (" + file.string() + "): " + ec.message());
  // tinygltf insists on an exact match; say so here, with both numbers.
  if (size != byte_length)
    return InvalidData(field + ": byteLength " + std::to_string(byte_length) + " but '" + uri + "' has " +
                       std::to_string(size) + " bytes");
  return OkStatus();
}

}  // namespace

Status CheckJsonSize(std::string_view json_text) {
  size_t objects = 0, values = 0;
  bool in_string = false, escaped = false;
  for (const char c : json_text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    else if (c == '{') ++objects, ++values;
    else if (c == '[' || c == ',') ++values;
  }
  if (objects > kMaxGltfJsonObjects)
    return InvalidData("JSON: " + std::to_string(objects) + " objects; at most " + std::to_string(kMaxGltfJsonObjects) +
                       " are read (accessors, nodes and the like; this is not a character scene)");
  if (values > kMaxGltfJsonValues)
    return InvalidData("JSON: about " + std::to_string(values) + " values; at most " +
                       std::to_string(kMaxGltfJsonValues) + " are read");
  return OkStatus();
}

Status CheckBuffers(std::string_view json_text, const std::string& base_dir, std::optional<size_t> glb_bin_bytes) {
  json doc;
  try {
    doc = json::parse(json_text.begin(), json_text.end());
  } catch (const json::exception& e) {  // parse_error, or out_of_range for a number like 1e999
    std::string what = e.what();
    const size_t bracket = what.find("] ");
    if (what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos) what = what.substr(bracket + 2);
    return InvalidData("JSON: " + what);
  }
  if (!doc.is_object()) return InvalidData("JSON: the top level is not an object");
  const auto buffers = doc.find("buffers");
  if (buffers == doc.end()) return OkStatus();
  if (!buffers->is_array()) return InvalidData("buffers: not an array");
  for (size_t i = 0; i < buffers->size(); ++i) {
    const std::string field = "buffers[" + std::to_string(i) + "]";
    const json& buffer = (*buffers)[i];
    if (!buffer.is_object()) return InvalidData(field + ": not an object");
    const auto length = buffer.find("byteLength");
    if (length == buffer.end() || !length->is_number_integer() || length->get<int64_t>() < 1)
      return InvalidData(field + ": byteLength is missing or not a positive integer");
    const size_t byte_length = length->get<size_t>();
    const auto uri = buffer.find("uri");
    if (uri == buffer.end()) {
      if (i != 0 || !glb_bin_bytes)
        return InvalidData(field + ": no uri" + (i == 0 && glb_bin_bytes == std::nullopt ? " and no GLB BIN chunk" : ""));
      if (byte_length > *glb_bin_bytes)
        return InvalidData(field + ": byteLength " + std::to_string(byte_length) + " exceeds the GLB BIN chunk (" +
                           std::to_string(*glb_bin_bytes) + " bytes)");
      continue;
    }
    if (!uri->is_string()) return InvalidData(field + ": uri is not a string");
    const std::string& text = uri->get_ref<const std::string&>();
    RETURN_IF_ERROR(text.rfind("data:", 0) == 0 ? CheckDataUri(field, text, byte_length)
                                                : CheckExternalFile(field, text, base_dir, byte_length));
  }
  return OkStatus();
}

}  // namespace mocapfill::gltf_internal
