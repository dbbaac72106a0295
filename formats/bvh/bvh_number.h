// Number parsing for BVH motion rows, the importer's hot loop (a CMU clip holds a quarter
// of a million values). Plain decimals ("-12.345", "5.1072e-06") take an exact fast path;
// anything else (long mantissas, large exponents, "nan") goes through std::from_chars.
// Both give the correctly rounded double, so results are identical. Values are short, so
// digits are read one at a time.
#pragma once

#include <charconv>
#include <cstddef>
#include <cstdint>

namespace mocapfill::bvh {

inline bool IsBvhSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

namespace internal {

constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

inline bool IsDigit(char c) { return static_cast<unsigned>(c - '0') < 10; }

}  // namespace internal

// Parses "[+-]digits[.digits][(e|E)[+-]digits]" ending at whitespace or `end`. With at
// most 19 digits, a digit string m up to 2^53 and a net power of ten p within +-22, m and
// 10^|p| are exact doubles and m * 10^p (or m / 10^-p) is one correctly rounded operation:
// the double from_chars returns (Clinger's fast path). Returns the end of the number, or
// nullptr when the fast path does not apply. Written for the row loop: digits counted by
// pointer differences, and the usual case (no exponent) returning before the exponent
// code, always as a division (by 10^0 for whole numbers), which keeps the usual case short.
inline const char* ParsePlainDecimal(const char* p, const char* end, double& value) {
  using internal::IsDigit;
  using internal::kPow10;
  const bool negative = p < end && *p == '-';
  if (p < end && (*p == '-' || *p == '+')) ++p;
  const char* const first_digit = p;
  uint64_t mantissa = 0;
  for (; p < end && IsDigit(*p); ++p) mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
  int power = 0;
  ptrdiff_t digits = 0;
  if (p < end && *p == '.') {
    const char* const point = p;
    for (++p; p < end && IsDigit(*p); ++p) mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
    power = -static_cast<int>(p - point - 1);
    digits = p - first_digit - 1;
  } else {
    digits = p - first_digit;
  }
  // More than 19 digits may have wrapped the 64-bit mantissa.
  if (static_cast<size_t>(digits - 1) >= 19 || mantissa > (uint64_t{1} << 53)) return nullptr;
  const double m = static_cast<double>(mantissa);
  if (p == end || IsBvhSpace(*p)) {  // at most 19 fraction digits: 10^-power is exact
    const double magnitude = m / kPow10[-power];
    value = negative ? -magnitude : magnitude;
    return p;
  }
  if (*p != 'e' && *p != 'E') return nullptr;  // "nan", garbage: the slow path decides
  ++p;
  const bool negative_exponent = p < end && *p == '-';
  if (p < end && (*p == '-' || *p == '+')) ++p;
  int exponent = 0, exponent_digits = 0;
  for (; p < end && IsDigit(*p) && exponent_digits < 4; ++p, ++exponent_digits) exponent = exponent * 10 + (*p - '0');
  if (exponent_digits == 0 || (p < end && !IsBvhSpace(*p))) return nullptr;  // "1e", a 5-digit exponent
  power += negative_exponent ? -exponent : exponent;
  if (power < -22 || power > 22) return nullptr;
  const double magnitude = power < 0 ? m / kPow10[-power] : m * kPow10[power];
  value = negative ? -magnitude : magnitude;
  return p;
}

inline bool IsFiniteNumber(double v) { return v - v == 0.0; }  // false for NaN and +-Inf

namespace internal {
// std::from_chars for the rest (long mantissas, large exponents, "nan", "inf"), with the
// fast path's '+' and its rule that a number ends at whitespace or `end`.
inline const char* ParseWithFromChars(const char* p, const char* end, double& value) {
  if (end - p >= 2 && *p == '+' && p[1] != '-') ++p;  // from_chars rejects a leading '+'
  const auto result = std::from_chars(p, end, value);
  if (result.ec != std::errc() || (result.ptr < end && !IsBvhSpace(*result.ptr))) return nullptr;
  return result.ptr;
}
}  // namespace internal

// Parses a number token starting at p: the fast path, else std::from_chars (callers check
// finiteness). The number must end at whitespace or `end`. Returns its end or nullptr.
inline const char* ParseNumber(const char* p, const char* end, double& value) {
  if (const char* q = ParsePlainDecimal(p, end, value)) return q;
  return internal::ParseWithFromChars(p, end, value);
}

// ParseNumber, refusing NaN and +-Inf (nullptr). The fast path's values are always finite,
// so only from_chars's are checked: no test of every value on the row loop's critical path.
inline const char* ParseFiniteNumber(const char* p, const char* end, double& value) {
  if (const char* q = ParsePlainDecimal(p, end, value)) return q;
  const char* q = internal::ParseWithFromChars(p, end, value);
  return q != nullptr && IsFiniteNumber(value) ? q : nullptr;
}

}  // namespace mocapfill::bvh
