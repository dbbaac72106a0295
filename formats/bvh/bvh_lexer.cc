#include "formats/bvh/bvh_lexer.h"

#include <algorithm>
#include <charconv>
#include <cstdio>

namespace mocapfill::bvh {

namespace {

constexpr size_t kMaxQuotedBytes = 40;

}  // namespace

bool EqualsIgnoreCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    char x = a[i], y = b[i];
    if (x >= 'A' && x <= 'Z') x = static_cast<char>(x - 'A' + 'a');
    if (y >= 'A' && y <= 'Z') y = static_cast<char>(y - 'A' + 'a');
    if (x != y) return false;
  }
  return true;
}

BvhLexer::BvhLexer(std::string_view text, std::string_view path) : text_(text), path_(path) {}

void BvhLexer::SkipWhitespace() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == ' ' || c == '\t') {
      ++pos_;
    } else if (c == '\n' || c == '\r') {
      ConsumeLineBreak();
    } else {
      break;
    }
  }
}

void BvhLexer::ConsumeLineBreak() {
  if (AtEnd()) return;
  if (text_[pos_] == '\r') {
    ++pos_;
    if (pos_ < text_.size() && text_[pos_] == '\n') ++pos_;
  } else if (text_[pos_] == '\n') {
    ++pos_;
  } else {
    return;
  }
  ++line_;
  line_start_ = pos_;
}

std::string_view BvhLexer::NextToken() {
  SkipWhitespace();
  token_location_ = Here();
  const size_t start = pos_;
  while (pos_ < text_.size() && !IsSpace(text_[pos_])) ++pos_;
  last_token_ = text_.substr(start, pos_ - start);
  return last_token_;
}

std::string_view BvhLexer::RestOfLine() {
  SkipBlanks();
  const size_t start = pos_;
  while (!AtLineEnd()) ++pos_;
  size_t end = pos_;
  while (end > start && (text_[end - 1] == ' ' || text_[end - 1] == '\t')) --end;
  return text_.substr(start, end - start);
}

Result<double> BvhLexer::NextNumber(std::string_view what) {
  const std::string_view token = NextToken();
  if (token.empty()) return ErrorAt(token_location_, "expected a number for " + std::string(what) + ", got the end of the file");
  const char* begin = token.data();
  const char* end = token.data() + token.size();
  if (*begin == '+') ++begin;
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec == std::errc::result_out_of_range)
    return ErrorAt(token_location_, "number " + Quote(token) + " for " + std::string(what) + " is out of range");
  if (ec != std::errc() || ptr != end)
    return ErrorAt(token_location_, "expected a number for " + std::string(what) + ", got " + Quote(token));
  if (!IsFiniteNumber(value))
    return ErrorAt(token_location_, "expected a finite number for " + std::string(what) + ", got " + Quote(token));
  return value;
}

Result<int64_t> BvhLexer::NextCount(std::string_view what, int64_t max_value) {
  const std::string_view token = NextToken();
  if (token.empty())
    return ErrorAt(token_location_, "expected a whole number for " + std::string(what) + ", got the end of the file");
  const char* begin = token.data();
  const char* end = token.data() + token.size();
  if (*begin == '+') ++begin;
  int64_t value = 0;
  const auto [ptr, ec] = std::from_chars(begin, end, value);
  if (ec == std::errc::result_out_of_range || (ec == std::errc() && ptr == end && value > max_value))
    return ErrorAt(token_location_, std::string(what) + " " + Quote(token) + " is out of range (at most " +
                                        std::to_string(max_value) + ")");
  if (ec != std::errc() || ptr != end || value < 0)
    return ErrorAt(token_location_,
                   "expected a non-negative whole number for " + std::string(what) + ", got " + Quote(token));
  return value;
}

Status BvhLexer::ErrorAt(TextLocation where, std::string_view message) const {
  return InvalidData(path_ + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) + ": " +
                     std::string(message));
}

std::string BvhLexer::QuoteTokenAt(size_t position) const {
  size_t end = position;
  while (end < text_.size() && !IsSpace(text_[end]) && end - position <= kMaxQuotedBytes) ++end;
  return Quote(text_.substr(position, end - position));
}

std::string BvhLexer::Quote(std::string_view token) {
  std::string out = "'";
  const size_t n = std::min(token.size(), kMaxQuotedBytes);
  for (size_t i = 0; i < n; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if (c < 0x20 || c >= 0x7f || c == '\'' || c == '\\') {
      char buffer[8];
      std::snprintf(buffer, sizeof(buffer), "\\x%02X", c);
      out += buffer;
    } else {
      out += static_cast<char>(c);
    }
  }
  if (token.size() > n) out += "...";
  return out + "'";
}

}  // namespace mocapfill::bvh
