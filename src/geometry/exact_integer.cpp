#include "geometry/exact_integer.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

namespace deltri::exact_integer {
namespace {

// A signed integer of any size: magnitude in 32-bit limbs from the least significant, no leading
// zero limbs (zero is the empty vector).
struct Big {
  std::vector<std::uint32_t> limbs;
  bool negative = false;
};

void trim(Big& x) {
  while (!x.limbs.empty() && x.limbs.back() == 0) x.limbs.pop_back();
  if (x.limbs.empty()) x.negative = false;
}

int compare_magnitude(const Big& x, const Big& y) {
  if (x.limbs.size() != y.limbs.size()) return x.limbs.size() < y.limbs.size() ? -1 : 1;
  for (std::size_t i = x.limbs.size(); i-- > 0;)
    if (x.limbs[i] != y.limbs[i]) return x.limbs[i] < y.limbs[i] ? -1 : 1;
  return 0;
}

// |x| + |y|
std::vector<std::uint32_t> add_magnitudes(const Big& x, const Big& y) {
  const std::size_t n = std::max(x.limbs.size(), y.limbs.size());
  std::vector<std::uint32_t> out(n + 1, 0);
  std::uint64_t carry = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint64_t t = carry + (i < x.limbs.size() ? x.limbs[i] : 0) + (i < y.limbs.size() ? y.limbs[i] : 0);
    out[i] = static_cast<std::uint32_t>(t);
    carry = t >> 32;
  }
  out[n] = static_cast<std::uint32_t>(carry);
  return out;
}

// |x| - |y|, given |x| >= |y|
std::vector<std::uint32_t> subtract_magnitudes(const Big& x, const Big& y) {
  std::vector<std::uint32_t> out(x.limbs.size(), 0);
  std::int64_t borrow = 0;
  for (std::size_t i = 0; i < x.limbs.size(); ++i) {
    std::int64_t t = static_cast<std::int64_t>(x.limbs[i]) - (i < y.limbs.size() ? y.limbs[i] : 0) - borrow;
    borrow = t < 0 ? 1 : 0;
    if (t < 0) t += std::int64_t{1} << 32;
    out[i] = static_cast<std::uint32_t>(t);
  }
  return out;
}

Big add(const Big& x, const Big& y) {
  Big z;
  if (x.negative == y.negative) {
    z.limbs = add_magnitudes(x, y);
    z.negative = x.negative;
  } else if (compare_magnitude(x, y) >= 0) {
    z.limbs = subtract_magnitudes(x, y);
    z.negative = x.negative;
  } else {
    z.limbs = subtract_magnitudes(y, x);
    z.negative = y.negative;
  }
  trim(z);
  return z;
}

Big negated(Big x) {
  if (!x.limbs.empty()) x.negative = !x.negative;
  return x;
}

Big subtract(const Big& x, const Big& y) { return add(x, negated(y)); }

Big multiply(const Big& x, const Big& y) {
  Big z;
  if (x.limbs.empty() || y.limbs.empty()) return z;
  z.limbs.assign(x.limbs.size() + y.limbs.size(), 0);
  for (std::size_t i = 0; i < x.limbs.size(); ++i) {
    std::uint64_t carry = 0;
    for (std::size_t j = 0; j < y.limbs.size(); ++j) {
      const std::uint64_t t = std::uint64_t{x.limbs[i]} * y.limbs[j] + z.limbs[i + j] + carry;
      z.limbs[i + j] = static_cast<std::uint32_t>(t);
      carry = t >> 32;
    }
    z.limbs[i + y.limbs.size()] = static_cast<std::uint32_t>(carry);
  }
  z.negative = x.negative != y.negative;
  trim(z);
  return z;
}

int sign(const Big& x) { return x.limbs.empty() ? 0 : (x.negative ? -1 : 1); }

// v = mantissa * 2^exponent exactly (mantissa < 2^53, exponent >= -1074).
struct Decomposed {
  std::uint64_t mantissa = 0;
  int exponent = 0;
  bool negative = false;
};

Decomposed decompose(double v) {
  const std::uint64_t bits = std::bit_cast<std::uint64_t>(v);
  const int biased = static_cast<int>((bits >> 52) & 0x7FF);
  Decomposed d;
  d.negative = (bits >> 63) != 0;
  d.mantissa = bits & ((std::uint64_t{1} << 52) - 1);
  if (biased != 0) d.mantissa |= std::uint64_t{1} << 52;
  d.exponent = (biased == 0 ? 1 : biased) - 1075;
  return d;
}

// The coordinates of one test as integers: value / 2^unit, where unit is the smallest exponent.
class Scaler {
 public:
  Scaler(const Point* points, int n) {
    for (int i = 0; i < n; ++i)
      for (const double v : {points[i].x, points[i].y}) {
        const Decomposed d = decompose(v);
        if (d.mantissa != 0) unit_ = std::min(unit_, d.exponent);
      }
  }

  Big operator()(double v) const {
    const Decomposed d = decompose(v);
    Big b;
    if (d.mantissa == 0) return b;
    const int shift = d.exponent - unit_;  // >= 0, < 2100
    b.limbs.assign(static_cast<std::size_t>(shift / 32) + 3, 0);
    const int word = shift / 32, bit = shift % 32;
    const unsigned __int128 shifted = static_cast<unsigned __int128>(d.mantissa) << bit;
    for (int k = 0; k < 3; ++k) b.limbs[static_cast<std::size_t>(word + k)] = static_cast<std::uint32_t>(shifted >> (32 * k));
    b.negative = d.negative;
    trim(b);
    return b;
  }

 private:
  int unit_ = 4096;
};

}  // namespace

bool coordinates_within(const Point* points, int n, int low, int high) {
  const double small = std::ldexp(1.0, low), large = std::ldexp(1.0, high);
  for (int i = 0; i < n; ++i)
    for (const double v : {points[i].x, points[i].y}) {
      const double m = std::fabs(v);
      if (m != 0.0 && !(m >= small && m <= large)) return false;
    }
  return true;
}

int orient2d_sign(const Point& a, const Point& b, const Point& c) {
  const Point pts[3] = {a, b, c};
  const Scaler s(pts, 3);
  const Big cx = s(c.x), cy = s(c.y);
  const Big acx = subtract(s(a.x), cx), acy = subtract(s(a.y), cy);
  const Big bcx = subtract(s(b.x), cx), bcy = subtract(s(b.y), cy);
  return sign(subtract(multiply(acx, bcy), multiply(acy, bcx)));
}

int incircle_sign(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point pts[4] = {a, b, c, d};
  const Scaler s(pts, 4);
  const Big dx = s(d.x), dy = s(d.y);
  const Big adx = subtract(s(a.x), dx), ady = subtract(s(a.y), dy);
  const Big bdx = subtract(s(b.x), dx), bdy = subtract(s(b.y), dy);
  const Big cdx = subtract(s(c.x), dx), cdy = subtract(s(c.y), dy);
  const auto lift = [](const Big& x, const Big& y) { return add(multiply(x, x), multiply(y, y)); };
  const auto cross = [](const Big& p, const Big& q, const Big& r, const Big& t) {
    return subtract(multiply(p, q), multiply(r, t));
  };
  const Big det = add(add(multiply(lift(adx, ady), cross(bdx, cdy, cdx, bdy)),
                          multiply(lift(bdx, bdy), cross(cdx, ady, adx, cdy))),
                      multiply(lift(cdx, cdy), cross(adx, bdy, bdx, ady)));
  return sign(det);
}

int dot_sign(const Point& a, const Point& b, const Point& p) {
  const Point pts[3] = {a, b, p};
  const Scaler s(pts, 3);
  const Big px = s(p.x), py = s(p.y);
  return sign(add(multiply(subtract(s(a.x), px), subtract(s(b.x), px)),
                  multiply(subtract(s(a.y), py), subtract(s(b.y), py))));
}

}  // namespace deltri::exact_integer
