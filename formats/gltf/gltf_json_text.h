// Internal to formats/gltf: the JSON text of the glTF writer (gltf_json_writer.cc), laid out
// as nlohmann::json's dump() lays out a tree (compact, or indented), but written as the
// members come: a tree would cost a std::map per object and a heap string per key, for every
// accessor and node of a file.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mocapfill::gltf_internal {

// Callers add an object's keys in sorted order, the order dump() prints a std::map-backed
// object in. An object or array that gets no member or element prints as null, as a json
// value that was never assigned does (tinygltf's serialiser leaves such values for empty
// arrays and objects), unless closed with EndObjectOrEmpty.
class JsonText {
 public:
  // `indent`: spaces per level, or -1 for compact text (dump()'s argument).
  JsonText(std::string& out, int indent) : out_(out), indent_(indent) { open_.reserve(16); }

  void BeginObject() { open_.push_back(0); }
  void EndObject() { Close('}', "null"); }
  void EndObjectOrEmpty() { Close('}', "{}"); }
  void BeginArray() { open_.push_back(0); }
  void EndArray() { Close(']', "null"); }

  // Before a member's value: its key, a literal that needs no escaping.
  void Key(const char* key) {
    Separator('{');
    out_ += '"';
    out_ += key;
    out_ += indent_ < 0 ? "\":" : "\": ";
  }
  // Before a member's value: any key, escaped as a string.
  void EscapedKey(const std::string& key);
  // Before an array element.
  void Element() { Separator('['); }

  void Int(int64_t v) { out_ += std::to_string(v); }
  void Unsigned(uint64_t v) { out_ += std::to_string(v); }
  void Bool(bool v) { out_ += v ? "true" : "false"; }
  void Null() { out_ += "null"; }
  // Shortest round-trip digits (nlohmann's to_chars), null for NaN and infinities.
  void Double(double v);
  // Throws nlohmann::json::type_error for text that is not UTF-8, as dump() does.
  void String(const std::string& s);
  // Text that needs no escaping, between quotes (a data URI).
  std::string& RawStringStart() {
    out_ += '"';
    return out_;
  }
  void RawStringEnd() { out_ += '"'; }

 private:
  void Separator(char open) {
    if (!open_.back()) {
      out_ += open;
      open_.back() = 1;
    } else {
      out_ += ',';
    }
    if (indent_ >= 0) NewLine(open_.size());
  }
  void Close(char close, const char* if_empty) {
    const bool opened = open_.back() != 0;
    open_.pop_back();
    if (!opened) {
      out_ += if_empty;
      return;
    }
    if (indent_ >= 0) NewLine(open_.size());
    out_ += close;
  }
  void NewLine(size_t depth) {
    out_ += '\n';
    out_.append(depth * static_cast<size_t>(indent_), ' ');
  }

  std::string& out_;
  const int indent_;
  std::vector<char> open_;  // per open object or array: whether it has printed its bracket
};

}  // namespace mocapfill::gltf_internal
