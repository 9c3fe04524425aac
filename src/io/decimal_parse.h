// Fast paths for the numbers that fill large input files: plain decimal integers and reals such
// as "0.3883639104740792" or "-2.5e-3". Each function either converts the text to exactly the
// value std::from_chars would give (bit for bit) and returns true, or returns false having decided
// nothing; the caller then uses std::from_chars, which also diagnoses every error. Neither accepts
// a leading '+' (the caller strips it, as it does for from_chars).
#pragma once

#include <bit>
#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

#include "geometry/extended_precision.h"

namespace deltri::decimal {

inline bool is_digit(char c) { return static_cast<unsigned char>(c - '0') < 10; }

// A plain decimal integer ("-123") of at most 18 digits, so that it cannot overflow a long long.
// `*end` is set to the first character after it.
inline bool parse_int(const char* p, const char* last, long long& value, const char** end) {
  const bool negative = p < last && *p == '-';
  if (negative) ++p;
  const char* digits = p;
  std::uint64_t m = 0;
  while (p < last && is_digit(*p) && p - digits < 18) m = m * 10 + static_cast<unsigned>(*p - '0'), ++p;
  if (p == digits || (p < last && is_digit(*p))) return false;  // no digits, or more than 18
  value = negative ? -static_cast<long long>(m) : static_cast<long long>(m);
  *end = p;
  return true;
}

namespace detail {

// Clinger's fast path: 10^0 .. 10^22 are exact doubles (5^22 < 2^53), and so is a mantissa up
// to 2^53, so one multiplication or division rounds once and gives the correctly rounded value.
// It needs double arithmetic without excess precision (not so on 32-bit x87).
constexpr bool kClingerAvailable = FLT_EVAL_METHOD == 0 && std::numeric_limits<double>::is_iec559;
inline constexpr double kPowers[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                     1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};
constexpr int kMaxPower = 22;
constexpr std::uint64_t kMaxMantissa = std::uint64_t{1} << 53;

// Shortest round-trip output has 17 significant digits for about a third of all doubles, and such
// mantissas exceed 2^53. The x87 extended format has a 64-bit significand: it holds any mantissa
// below 2^64 exactly, and 10^0 .. 10^27 too (5^27 < 2^64), so m * 10^k and m / 10^k are rounded
// once, to 64 bits. Rounding that to a double is then correct, unless the 64-bit result lies
// exactly halfway between two doubles: the true value may be on either side of it (a midpoint
// strictly between the true value and the 64-bit result would itself be a closer 64-bit number).
// The results lie within [1e-27, 2^64 * 1e27], where every double is normal, so "halfway" is a
// matter of the 11 significand bits a double drops.
#if defined(__x86_64__) || defined(__i386__)
constexpr bool kExtendedAvailable = std::numeric_limits<long double>::digits == 64;
#else
constexpr bool kExtendedAvailable = false;  // the significand's place in memory is known only for x87
#endif
inline constexpr long double kExtendedPowers[] = {
    1e0L,  1e1L,  1e2L,  1e3L,  1e4L,  1e5L,  1e6L,  1e7L,  1e8L,  1e9L,  1e10L, 1e11L, 1e12L, 1e13L,
    1e14L, 1e15L, 1e16L, 1e17L, 1e18L, 1e19L, 1e20L, 1e21L, 1e22L, 1e23L, 1e24L, 1e25L, 1e26L, 1e27L};
constexpr int kMaxExtendedPower = 27;

// The x87 precision control could have been lowered to 53 bits by foreign code (or valgrind runs
// the program); then extended arithmetic rounds like double arithmetic and the reasoning above
// fails: extended_precision_active (geometry/extended_precision.h) says so.

// Whether the 64-bit significand of x has the bit pattern of a midpoint between two doubles:
// the dropped 11 bits are exactly 100 0000 0000.
inline bool halfway_between_doubles(long double x) {
  std::uint64_t significand;  // x87 layout: the significand is the first 8 bytes, little-endian
  std::memcpy(&significand, &x, sizeof significand);
  return (significand & 0x7FF) == 0x400;
}

// Eight digits at a time (SWAR): on little-endian machines eight ASCII bytes loaded as one
// 64-bit word are checked and converted with a few multiplications, instead of eight dependent
// multiply-adds. The accumulating loop below is what bounds the speed of reading coordinates.
constexpr bool kEightAtATime = std::endian::native == std::endian::little;

inline std::uint64_t load8(const char* p) {
  std::uint64_t word;
  std::memcpy(&word, p, sizeof word);
  return word;
}

inline bool eight_digits(std::uint64_t word) {
  // In a byte below '0', byte - '0' wraps around into the high bit; in one above '9' (0x80 and
  // up included), byte + 0x46 or byte - '0' has the high bit set. Borrows and carries between
  // bytes start only at bytes that are flagged themselves, so they cannot hide a non-digit.
  return (((word + 0x4646464646464646) | (word - 0x3030303030303030)) & 0x8080808080808080) == 0;
}

inline std::uint32_t eight_digit_value(std::uint64_t word) {
  word -= 0x3030303030303030;                        // bytes d0 (first) .. d7, each 0..9
  word = word * 10 + (word >> 8);                    // pairs: byte 2i holds 10*d(2i) + d(2i+1)
  const std::uint64_t pairs = 0x000000FF000000FF;    // pairs 0 and 2, then (after >> 16) 1 and 3
  word = ((word & pairs) * (100 + (1000000ULL << 32)) + ((word >> 16) & pairs) * (1 + (10000ULL << 32))) >> 32;
  return static_cast<std::uint32_t>(word);
}

// Appends the run of digits at p to m (m = m * 10 + digit for each) and returns its end.
// m wraps around when the run is too long; callers count the digits and give up then.
inline const char* accumulate_digits(const char* p, const char* last, std::uint64_t& m) {
  if constexpr (kEightAtATime) {
    while (last - p >= 8 && eight_digits(load8(p))) {
      m = m * 100000000 + eight_digit_value(load8(p));
      p += 8;
    }
  }
  for (; p < last && is_digit(*p); ++p) m = m * 10 + static_cast<unsigned>(*p - '0');
  return p;
}

inline const char* skip_zeros(const char* p, const char* last) {
  while (p < last && *p == '0') ++p;
  return p;
}

}  // namespace detail

// A decimal real: optional '-', digits with an optional '.', optional exponent ('e' or 'E',
// optional sign, digits). Succeeds when the significant digits (leading zeros do not count) form
// a mantissa below 10^19 and the value is exactly computable as above. `*end` is set to the first
// character after the number.
inline bool parse_double(const char* p, const char* last, double& value, const char** end) {
  const bool negative = p < last && *p == '-';
  if (negative) ++p;
  const char* const begin = p;
  std::uint64_t m = 0;
  p = detail::skip_zeros(p, last);
  const char* significant_begin = p;
  p = detail::accumulate_digits(p, last, m);
  std::ptrdiff_t significant = p - significant_begin;
  bool any_digit = p != begin;
  std::ptrdiff_t scale = 0;  // value = m * 10^scale; wide: a field may have millions of digits
  if (p < last && *p == '.') {
    const char* const fraction = ++p;
    if (significant == 0) p = detail::skip_zeros(p, last);  // "0.000123": zeros only scale
    significant_begin = p;
    p = detail::accumulate_digits(p, last, m);
    significant += p - significant_begin;
    scale = -(p - fraction);
    any_digit = any_digit || p != fraction;
  }
  if (!any_digit || significant > 19) return false;
  if (p < last && (*p == 'e' || *p == 'E')) {
    const char* q = p + 1;
    const bool negative_exponent = q < last && *q == '-';
    if (q < last && (*q == '-' || *q == '+')) ++q;
    const char* digits = q;
    int exponent = 0;
    while (q < last && is_digit(*q) && q - digits < 4) exponent = exponent * 10 + (*q - '0'), ++q;
    // "1e" and "1e+" end the number before the 'e' in from_chars; five-digit exponents are
    // beyond any fast path anyway.
    if (q == digits || (q < last && is_digit(*q))) return false;
    scale += negative_exponent ? -exponent : exponent;
    p = q;
  }
  double result;
  if (m == 0) {
    result = 0.0;
  } else if (detail::kClingerAvailable && m <= detail::kMaxMantissa && scale >= -detail::kMaxPower &&
             scale <= detail::kMaxPower) {
    const double d = static_cast<double>(m);  // exact
    result = scale < 0 ? d / detail::kPowers[-scale] : d * detail::kPowers[scale];
  } else if (detail::kExtendedAvailable && scale >= -detail::kMaxExtendedPower &&
             scale <= detail::kMaxExtendedPower) {
    if (!extended_precision_active()) return false;
    const long double x = static_cast<long double>(m);  // exact: m < 10^19 < 2^64
    const long double q = scale < 0 ? x / detail::kExtendedPowers[-scale] : x * detail::kExtendedPowers[scale];
    if (detail::halfway_between_doubles(q)) return false;
    result = static_cast<double>(q);
  } else {
    return false;
  }
  value = negative ? -result : result;
  *end = p;
  return true;
}

}  // namespace deltri::decimal
