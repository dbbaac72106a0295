// A cursor over BVH text: whitespace-separated tokens as string_views (no allocation),
// numbers through std::from_chars, and the line and column of every position so that
// errors read "walk.bvh:135:17: expected a number, got 'abc'". Any line ending (LF,
// CRLF, CR), tabs, a missing final newline and lines of any length are accepted.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "formats/bvh/bvh_number.h"
#include "processing/core/status.h"

namespace mocapfill::bvh {

// 1-based line and column (columns count bytes, a tab is one column).
struct TextLocation {
  int64_t line = 1;
  int64_t column = 1;
};

class BvhLexer {
 public:
  BvhLexer(std::string_view text, std::string_view path);

  bool AtEnd() const { return pos_ >= text_.size(); }
  // True at a line break or at the end of the text.
  bool AtLineEnd() const { return AtEnd() || text_[pos_] == '\n' || text_[pos_] == '\r'; }
  size_t position() const { return pos_; }
  size_t remaining_bytes() const { return text_.size() - pos_; }
  std::string_view TextFromHere() const { return text_.substr(pos_); }
  TextLocation Here() const { return {line_, static_cast<int64_t>(pos_ - line_start_) + 1}; }

  // Skips spaces and tabs, staying on the current line.
  void SkipBlanks() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) ++pos_;
  }
  // Skips all whitespace including line breaks.
  void SkipWhitespace();
  // Consumes one line break (LF, CR or CRLF) if the cursor is on one.
  void ConsumeLineBreak();

  // The next whitespace-delimited token (after any whitespace), or "" at the end of the text.
  // token_location() gives where it started.
  std::string_view NextToken();
  TextLocation token_location() const { return token_location_; }
  std::string_view last_token() const { return last_token_; }
  // The rest of the current line with surrounding blanks removed; leaves the cursor at the line end.
  std::string_view RestOfLine();

  // Reads the next token as a finite number / a non-negative integer that fits `max_value`.
  // `what` names the value in error messages ("the X offset of joint 'Hips'").
  Result<double> NextNumber(std::string_view what);
  Result<int64_t> NextCount(std::string_view what, int64_t max_value);

  // Raw access for the motion-row loop, which scans a line with local pointers and
  // then moves the cursor; MoveWithinLine must not cross a line break.
  const char* cursor() const { return text_.data() + pos_; }
  const char* text_end() const { return text_.data() + text_.size(); }
  void MoveWithinLine(const char* p) { pos_ = static_cast<size_t>(p - text_.data()); }

  // An InvalidData status "path:line:col: message".
  Status ErrorAt(TextLocation where, std::string_view message) const;
  // The token starting at `position`, quoted for messages: at most 40 bytes, with
  // non-printable bytes escaped as \xNN so binary garbage stays readable.
  std::string QuoteTokenAt(size_t position) const;
  static std::string Quote(std::string_view token);

  const std::string& path() const { return path_; }

 private:
  static bool IsSpace(char c) { return IsBvhSpace(c); }

  std::string_view text_;
  std::string path_;
  size_t pos_ = 0;
  int64_t line_ = 1;
  size_t line_start_ = 0;
  TextLocation token_location_;
  std::string_view last_token_;
};

// Case-insensitive ASCII comparison for keywords ("End Site", "End site").
bool EqualsIgnoreCase(std::string_view a, std::string_view b);

}  // namespace mocapfill::bvh
