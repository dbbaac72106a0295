// Number parsing for BVH motion rows, the importer's hot loop (a CMU clip holds a quarter
// of a million values). Plain decimals ("-12.345") take an exact fast path that reads up
// to eight digits at a time; anything else (exponents, long mantissas) goes through
// std::from_chars. Both give the correctly rounded double, so results are identical.
#pragma once

#include <bit>
#include <charconv>
#include <cstdint>
#include <cstring>

namespace mocapfill::bvh {

inline bool IsBvhSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

namespace internal {

constexpr uint64_t kPow10Int[] = {1,         10,         100,         1000,         10000,        100000,
                                  1000000,   10000000,   100000000};
constexpr double kPow10[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                             1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr uint64_t kAsciiZeros = 0x3030303030303030ULL;

// Number of leading ASCII digits among 8 bytes loaded little-endian (first byte lowest).
// A byte b is a digit iff x = b ^ '0' is below 10; masking with 0x7F before adding 0x76
// keeps every byte's sum below 0x100, so no carry crosses into the next byte.
inline int LeadingDigits(uint64_t bytes) {
  const uint64_t x = bytes ^ kAsciiZeros;
  const uint64_t non_digit = (((x & 0x7F7F7F7F7F7F7F7FULL) + 0x7676767676767676ULL) | x) & 0x8080808080808080ULL;
  return non_digit == 0 ? 8 : std::countr_zero(non_digit) / 8;
}

// Value of 8 ASCII digits, first byte most significant (the SWAR reduction of fast_float).
inline uint32_t EightDigits(uint64_t bytes) {
  uint64_t v = bytes - kAsciiZeros;
  v = (v * 10) + (v >> 8);
  v = (((v & 0x000000FF000000FFULL) * (100 + (1000000ULL << 32))) +
       (((v >> 16) & 0x000000FF000000FFULL) * (1 + (10000ULL << 32)))) >>
      32;
  return static_cast<uint32_t>(v);
}

// Value of the first n (1..8) digits of `bytes`: shift them to the top and pad with '0's.
inline uint32_t FirstDigits(uint64_t bytes, int n) {
  if (n == 8) return EightDigits(bytes);
  const int pad_bits = 8 * (8 - n);
  return EightDigits((bytes << pad_bits) | (kAsciiZeros >> (64 - pad_bits)));
}

// Accumulates a run of digits into mantissa; returns the end of the run.
inline const char* ReadDigits(const char* p, const char* end, uint64_t& mantissa, int& digits) {
  if constexpr (std::endian::native == std::endian::little) {
    while (end - p >= 8) {
      uint64_t bytes;
      std::memcpy(&bytes, p, 8);
      const int n = LeadingDigits(bytes);
      if (n == 0) return p;
      mantissa = mantissa * kPow10Int[n] + FirstDigits(bytes, n);
      p += n;
      digits += n;
      if (n < 8 || digits > 19) return p;
    }
  }
  for (; p < end && static_cast<unsigned>(*p - '0') < 10 && digits <= 19; ++p, ++digits)
    mantissa = mantissa * 10 + static_cast<unsigned>(*p - '0');
  return p;
}

}  // namespace internal

// Parses "[+-]digits[.digits]" ending at whitespace or `end`. With at most 19 digits,
// a digit string up to 2^53 and at most 22 fraction digits, m / 10^k is a single
// correctly rounded division of exact doubles: the double from_chars returns (Clinger's
// fast path). Returns the end of the number, or nullptr when the fast path does not apply.
inline const char* ParsePlainDecimal(const char* p, const char* end, double& value) {
  const bool negative = p < end && *p == '-';
  if (p < end && (*p == '-' || *p == '+')) ++p;
  uint64_t mantissa = 0;
  int digits = 0;
  p = internal::ReadDigits(p, end, mantissa, digits);
  int fraction_digits = 0;
  if (p < end && *p == '.') {
    const int integer_digits = digits;
    p = internal::ReadDigits(p + 1, end, mantissa, digits);
    fraction_digits = digits - integer_digits;
  }
  // More than 19 digits may have wrapped the 64-bit mantissa.
  if (digits == 0 || digits > 19 || fraction_digits > 22 || mantissa > (uint64_t{1} << 53)) return nullptr;
  if (p < end && !IsBvhSpace(*p)) return nullptr;  // exponent, "nan", garbage: the slow path decides
  const double magnitude = static_cast<double>(mantissa) / internal::kPow10[fraction_digits];
  value = negative ? -magnitude : magnitude;
  return p;
}

// Parses a number token starting at p: the fast path, else std::from_chars (which
// accepts exponents, "nan" and "inf"; callers check finiteness). The number must end at
// whitespace or `end`. Returns the end of the number or nullptr.
inline const char* ParseNumber(const char* p, const char* end, double& value) {
  if (const char* q = ParsePlainDecimal(p, end, value)) return q;
  if (end - p >= 2 && *p == '+' && p[1] != '-') ++p;  // from_chars rejects a leading '+'
  const auto result = std::from_chars(p, end, value);
  if (result.ec != std::errc() || (result.ptr < end && !IsBvhSpace(*result.ptr))) return nullptr;
  return result.ptr;
}

inline bool IsFiniteNumber(double v) { return v - v == 0.0; }  // false for NaN and +-Inf

}  // namespace mocapfill::bvh
