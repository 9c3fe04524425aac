// The shortest decimal that reads back as value v is the one with the fewest fractional digits
// inside v's rounding interval (the reals that round to v), and among those the closest to v;
// that is what std::to_chars produces. Here the interval's ends are computed exactly in 128-bit
// integers at one precision with 17 or 18 significant digits, which always holds a candidate;
// dropping trailing digits while a candidate survives then gives the shortest.
//
// v = M * 2^E with M in [2^52, 2^53). In units of 2^(E-2), v is c = 4M, its neighbours' midpoints
// are 4M - 2 and 4M + 2 (4M - 1 below a power of two, where the gap below is half as wide), and
// a decimal exactly on a midpoint reads back as v only when M is even (ties go to even).
#include "io/shortest_fixed.h"

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "io/digit_pairs.h"

namespace deltri {

#if defined(__SIZEOF_INT128__)
namespace {

using u64 = std::uint64_t;
using u128 = unsigned __int128;

constexpr auto kPow10 = [] {
  struct Table {
    u64 v[20];
  } t{};
  t.v[0] = 1;
  for (int i = 1; i < 20; ++i) t.v[i] = t.v[i - 1] * 10;
  return t;
}();

// c * 10^p / 2^s for c * 10^p < 2^128 and a quotient below 2^64: the floor and the remainder.
struct Scaled {
  u64 floor;
  u128 remainder;
};
Scaled scale(u64 c, int p, int s) {
  const u128 x = static_cast<u128>(c) * kPow10.v[p];
  return {static_cast<u64>(x >> s), x & ((u128{1} << s) - 1)};
}

// Rounds value * 10^p (given as `at`, with s fraction bits) to a multiple of 10^j, ties to even,
// and returns the multiple divided by 10^j; q is floor(at.floor / 10^j).
u64 nearest(const Scaled& at, u64 q, int j, int s) {
  const u64 t = kPow10.v[j];
  const u64 r = at.floor - q * t;
  bool up;
  if (2 * r + 2 <= t) up = false;
  else if (2 * r > t) up = true;
  else if (2 * r == t) up = at.remainder != 0 || (q & 1);
  else {  // t == 1: compare the fraction with one half
    const u128 half = u128{1} << (s - 1);
    up = at.remainder > half || (at.remainder == half && (q & 1));
  }
  return q + (up ? 1 : 0);
}


// Exactly four digits of v < 10^4, and exactly eight of v < 10^8: the pairs are independent of
// each other, unlike a loop that divides the same number again and again.
void put_4(char* p, std::uint32_t v) {
  std::memcpy(p, kDigitPairs.text + 2 * (v / 100), 2);
  std::memcpy(p + 2, kDigitPairs.text + 2 * (v % 100), 2);
}
void put_8(char* p, std::uint32_t v) {
  put_4(p, v / 10000);
  put_4(p + 4, v % 10000);
}

int digit_count(u64 n) {
  const int t = (std::bit_width(n | 1) * 1233) >> 12;  // log10(2) ~ 1233 / 4096
  return t - (n < kPow10.v[t]) + 1;
}

// n * 10^-fraction_digits in fixed notation, for n < 10^19 and -2 <= fraction_digits, with at
// most one zero after the point before n's digits. Copies are of fixed size (the caller allows
// scratch space past the end), which is much cheaper than exact-length copies.
char* put_fixed(char* p, u64 n, int fraction_digits) {
  char all[48];  // n with leading zeros in all[0, 20), then zeros as scratch for fixed-size copies
  put_4(all, static_cast<std::uint32_t>(n / 10000000000000000u));
  put_8(all + 4, static_cast<std::uint32_t>(n / 100000000 % 100000000));
  put_8(all + 12, static_cast<std::uint32_t>(n % 100000000));
  std::memset(all + 20, '0', 28);
  const int digits = digit_count(n);
  const char* d = all + 20 - digits;
  if (fraction_digits <= 0) {  // whole number; the zeros after d come from the scratch
    std::memcpy(p, d, 24);
    return p + digits - fraction_digits;
  }
  if (digits > fraction_digits) {
    const int whole = digits - fraction_digits;
    std::memcpy(p, d, 4);  // v < 1000: at most three whole digits
    p[whole] = '.';
    std::memcpy(p + whole + 1, d + whole, 20);
    return p + digits + 1;
  }
  std::memcpy(p, "0.00", 4);
  const int zeros = fraction_digits - digits;
  std::memcpy(p + 2 + zeros, d, 20);
  return p + 2 + fraction_digits;
}

}  // namespace

char* format_shortest_fixed(char* p, double value) {
  const double a = std::fabs(value);
  if (!(a >= 0.01 && a < 1000.0)) return nullptr;
  // Whole numbers (grids) are common and would need many digits dropped one at a time.
  const auto whole = static_cast<std::uint32_t>(a);
  if (whole == a) {
    if (value < 0) *p++ = '-';
    if (whole >= 100) *p++ = static_cast<char>('0' + whole / 100);
    if (whole >= 10) *p++ = static_cast<char>('0' + whole / 10 % 10);
    *p++ = static_cast<char>('0' + whole % 10);
    return p;
  }
  const u64 bits = std::bit_cast<u64>(a);
  const u64 fraction = bits & ((u64{1} << 52) - 1);
  const u64 m = fraction | (u64{1} << 52);
  const int s = 2 - (static_cast<int>(bits >> 52) - 1075);  // units of 2^(E-2): 2^-s
  const bool ends_included = (m & 1) == 0;
  // value * 10^precision lies in [10^17, 10^18] (near enough: the tests against 0.1 etc. are
  // approximate): 17 or 18 digits hold a candidate for any double, and the interval ends fit 64
  // bits.
  const int precision = a >= 100.0 ? 15 : a >= 10.0 ? 16 : a >= 1.0 ? 17 : a >= 0.1 ? 18 : 19;
  const Scaled lo = scale(4 * m - (fraction == 0 ? 1 : 2), precision, s);
  const Scaled hi = scale(4 * m + 2, precision, s);
  const u64 first = lo.floor + (lo.remainder == 0 && ends_included ? 0 : 1);
  const u64 last = hi.floor - (hi.remainder == 0 && !ends_included ? 1 : 0);
  // Drop trailing digits while a candidate survives: [lowest, highest] are the candidates with j
  // digits dropped, ceil(first / 10^j) and floor(last / 10^j); `q` follows floor(value / 10^j).
  const Scaled at = scale(4 * m, precision, s);
  u64 lowest = first, highest = last, q = at.floor;
  int j = 0;
  while (j < 18) {
    const u64 next_lowest = lowest / 10 + (lowest % 10 != 0), next_highest = highest / 10;
    if (next_lowest > next_highest) break;
    lowest = next_lowest, highest = next_highest, q /= 10;
    ++j;
  }
  u64 n = nearest(at, q, j, s);
  n = n < lowest ? lowest : n > highest ? highest : n;
  if (value < 0) *p++ = '-';
  return put_fixed(p, n, precision - j);
}

#else

char* format_shortest_fixed(char*, double) { return nullptr; }

#endif

}  // namespace deltri
