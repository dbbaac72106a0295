// Str(n): an integer as decimal text, for the field paths in the glTF code's messages
// ("accessors[3]: count 5 ..."). A template, so that every integer type reads as itself.
#pragma once

#include <string>
#include <type_traits>

namespace mocapfill::gltf_internal {

template <typename Integer, typename = std::enable_if_t<std::is_integral_v<Integer>>>
std::string Str(Integer value) {
  return std::to_string(value);
}

}  // namespace mocapfill::gltf_internal
