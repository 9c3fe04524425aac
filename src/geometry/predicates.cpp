// The adaptive stages of orient2d and incircle (Shewchuk 1997, sections 4.2-4.4).
//
// Stage B evaluates the determinant exactly, but from the rounded coordinate differences; if those
// differences were themselves exact (the common case for nearby points) that is the true answer.
// Stage C adds the first-order effect of the differences' roundoff in floating point. Stage D
// evaluates the determinant exactly from the input coordinates. Each stage stops as soon as its
// error bound proves the sign.
//
// incircle tries cheaper ways to the exact sign before stage B (ours, not the paper's), in this
// order: comparisons that find the corners of an axis-parallel rectangle (exactly zero); plain doubles when the differences are exact and span at most 12 bits (lattice points,
// whose zeros no filter can decide); the filter's evaluation repeated in long double, whose bound
// with long double's unit roundoff is 2^11 times tighter where long double has a 64-bit significand
// (x87, as on x86-64 Linux) and which decides most of the nearly cocircular quadruples of points
// rounded onto a circle (the analysis is the filter's: the inputs are doubles, exact in long
// double, whose exponent range is wider; compiled out where long double is no wider than double,
// skipped where its arithmetic is not carried out in 64 bits: extended_precision.h);
// and, with exact differences, double-word arithmetic with a proven bound, then 256-bit integers.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

#include "geometry/expansion.h"
#include "geometry/exact_determinants.h"
#include "geometry/exact_integer.h"
#include "geometry/extended_precision.h"
#include "geometry/predicates.h"

namespace deltri {
namespace {

using namespace deltri::expansion;
using bounds::kEpsilon;

// Error bounds of the later stages, from the paper's analysis.
constexpr double kResultBound = (3.0 + 8.0 * kEpsilon) * kEpsilon;
constexpr double kOrientB = (2.0 + 12.0 * kEpsilon) * kEpsilon;
constexpr double kOrientC = (9.0 + 64.0 * kEpsilon) * kEpsilon * kEpsilon;
constexpr double kIncircleB = (4.0 + 48.0 * kEpsilon) * kEpsilon;
constexpr double kIncircleC = (44.0 + 576.0 * kEpsilon) * kEpsilon * kEpsilon;

// The coordinate ranges, as powers of two, where the expansion stages are exact (predicates.h).
constexpr int kOrientLow = -400, kOrientHigh = 500;
constexpr int kIncircleLow = -170, kIncircleHigh = 250;

bool decided(double det, double bound) { return det > bound || -det > bound; }

constexpr bool kWideLongDouble = std::numeric_limits<long double>::digits > 53;

// The filter's determinant and bound in long double; true (with det set) if they prove the sign.
bool incircle_extended(const Point& a, const Point& b, const Point& c, const Point& d, double& det) {
  using R = long double;
  constexpr R u = std::numeric_limits<R>::epsilon() / 2;  // unit roundoff
  constexpr R bound_factor = (10 + 96 * u) * u;
  const PlainIncircle<R> plain =
      plain_incircle<R>(R(a.x) - d.x, R(a.y) - d.y, R(b.x) - d.x, R(b.y) - d.y, R(c.x) - d.x, R(c.y) - d.y);
  const R value = plain.det;
  if (!(std::fabs(value) > bound_factor * plain.permanent)) return false;
  // The sign is proven; report it in a double that keeps it (a tiny value must not round to 0).
  det = value > 0 ? std::max(static_cast<double>(value), std::numeric_limits<double>::denorm_min())
                  : std::min(static_cast<double>(value), -std::numeric_limits<double>::denorm_min());
  return true;
}

// Whether the four points are the corners of an axis-parallel rectangle (d, a point sharing its x,
// one sharing its y, and the last sharing the x of one and the y of the other). Their lifts
// x^2 + y^2 add a function of x to one of y, so on such a 2 x 2 grid they are coplanar and the
// determinant is exactly zero, whatever the spacing. Refinement of a strip or a grid of rectangles
// whose sides are not dyadic (a 1 x 1e-6 rectangle) meets such quadruples at every split, and
// each otherwise went through every stage below to find the zero.
bool rectangle_corners(const Point& a, const Point& b, const Point& c, const Point& d) {
  const Point* others[3] = {&a, &b, &c};
  for (int i = 0; i < 3; ++i) {
    if (others[i]->x != d.x) continue;
    for (int j = 0; j < 3; ++j) {
      if (j == i || others[j]->y != d.y) continue;
      const Point& last = *others[3 - i - j];
      if (last.x == others[j]->x && last.y == others[i]->y) return true;
    }
  }
  return false;
}

// (dx^2 + dy^2) * minor exactly, for single-double dx, dy and minor of at most 4 components.
int lifted_minor(const double* minor, int n, double dx, double dy, double* out) {
  double x1[8], x2[16], y1[8], y2[16];
  const int x1n = scale(minor, n, dx, x1);
  const int x2n = scale(x1, x1n, dx, x2);
  const int y1n = scale(minor, n, dy, y1);
  const int y2n = scale(y1, y1n, dy, y2);
  return sum(x2, x2n, y2, y2n, out);
}

// The first-order change of lift * minor when the differences move by their tails.
double first_order(double dx, double dy, double dx_tail, double dy_tail, double minor,
                   double minor_tail_effect) {
  return (dx * dx + dy * dy) * minor_tail_effect + 2.0 * (dx * dx_tail + dy * dy_tail) * minor;
}

// The six coordinate differences of an incircle test as integers times a common power of two:
// d[k] = m[k] * 2^low, and every |m[k]| < 2^width.
struct ScaledDifferences {
  std::int64_t m[6] = {0, 0, 0, 0, 0, 0};
  int width = 0;
  int low = 0;  // the power of two of the unit
  // The plain and double-word evaluations stay clear of underflow and overflow: their smallest
  // terms (2^(4 low), their roundoff u^2 below that) stay normal, their largest below 2^1000.
  bool fits_doubles() const { return low >= -225 && low + width <= 245; }
};

// False for subnormals, non-finite values, or a width beyond 62 bits.
bool scale_to_integers(const double (&d)[6], ScaledDifferences& out) {
  std::uint64_t mantissa[6] = {0, 0, 0, 0, 0, 0};
  int exponent[6] = {0, 0, 0, 0, 0, 0};
  int low = 4096, high = -4096;
  for (int k = 0; k < 6; ++k) {
    if (d[k] == 0.0) continue;
    const std::uint64_t bits = std::bit_cast<std::uint64_t>(d[k]);
    const int biased = static_cast<int>((bits >> 52) & 0x7FF);
    if (biased == 0 || biased == 0x7FF) return false;
    mantissa[k] = (bits & ((std::uint64_t{1} << 52) - 1)) | (std::uint64_t{1} << 52);
    exponent[k] = biased - 1075;  // d = mantissa * 2^exponent
    low = std::min(low, exponent[k] + std::countr_zero(mantissa[k]));
    high = std::max(high, exponent[k] + 53);
  }
  if (high - low > 62) return false;
  out.width = std::max(0, high - low);
  out.low = low;
  for (int k = 0; k < 6; ++k) {
    if (mantissa[k] == 0) continue;
    const int shift = exponent[k] - low;  // >= -52 (trailing zeros only) and <= 9
    const std::uint64_t v = shift >= 0 ? mantissa[k] << shift : mantissa[k] >> -shift;
    out.m[k] = d[k] < 0.0 ? -static_cast<std::int64_t>(v) : static_cast<std::int64_t>(v);
  }
  return true;
}

// 256-bit two's complement integers, four 64-bit limbs from the least significant.
using u128 = unsigned __int128;
using Int256 = std::array<std::uint64_t, 4>;

Int256 multiply_256(u128 a, u128 b) {
  const std::uint64_t a0 = static_cast<std::uint64_t>(a), a1 = static_cast<std::uint64_t>(a >> 64);
  const std::uint64_t b0 = static_cast<std::uint64_t>(b), b1 = static_cast<std::uint64_t>(b >> 64);
  const u128 p00 = u128{a0} * b0, p01 = u128{a0} * b1, p10 = u128{a1} * b0, p11 = u128{a1} * b1;
  const u128 mid = (p00 >> 64) + static_cast<std::uint64_t>(p01) + static_cast<std::uint64_t>(p10);
  const u128 top = (p01 >> 64) + (p10 >> 64) + p11 + (mid >> 64);
  return {static_cast<std::uint64_t>(p00), static_cast<std::uint64_t>(mid),
          static_cast<std::uint64_t>(top), static_cast<std::uint64_t>(top >> 64)};
}

Int256 add_256(const Int256& x, const Int256& y) {
  Int256 z{};
  std::uint64_t carry = 0;
  for (int i = 0; i < 4; ++i) {
    const u128 t = u128{x[i]} + y[i] + carry;
    z[i] = static_cast<std::uint64_t>(t);
    carry = static_cast<std::uint64_t>(t >> 64);
  }
  return z;
}

Int256 negate_256(const Int256& x) {
  const Int256 inverted{~x[0], ~x[1], ~x[2], ~x[3]};
  return add_256(inverted, {1, 0, 0, 0});
}

// lift * minor for a minor given as the difference of two products of 63-bit integers.
Int256 lifted_term(std::int64_t x, std::int64_t y, std::int64_t p, std::int64_t q, std::int64_t r,
                   std::int64_t s) {
  const __int128 minor = static_cast<__int128>(p) * q - static_cast<__int128>(r) * s;  // < 2^125
  const u128 lift = static_cast<u128>(static_cast<__int128>(x) * x) + static_cast<u128>(static_cast<__int128>(y) * y);
  const Int256 magnitude = multiply_256(lift, static_cast<u128>(minor < 0 ? -minor : minor));
  return minor < 0 ? negate_256(magnitude) : magnitude;
}

// Stage B's determinant exactly in integers (|terms| < 2^252, their sum < 2^254); reached by
// exactly cocircular points whose differences span too many bits for the grid path (the vertices of
// a polygon placed symmetrically about its centre), which the double-word stage cannot decide.
double incircle_in_integers(const ScaledDifferences& s) {
  const std::int64_t* m = s.m;  // adx, ady, bdx, bdy, cdx, cdy
  const Int256 det = add_256(add_256(lifted_term(m[0], m[1], m[2], m[5], m[4], m[3]),
                                     lifted_term(m[2], m[3], m[4], m[1], m[0], m[5])),
                             lifted_term(m[4], m[5], m[0], m[3], m[2], m[1]));
  if (static_cast<std::int64_t>(det[3]) < 0) return -1.0;
  return (det[0] | det[1] | det[2] | det[3]) != 0 ? 1.0 : 0.0;
}

// A double-word number hi + lo, |lo| <= ulp(hi) / 2 (Joldes, Muller and Popescu, "Tight and
// rigorous error bounds for basic building blocks of double-word arithmetic", 2017).
struct DoubleWord {
  double hi, lo;
};

DoubleWord exact_product(double a, double b) {
  DoubleWord p;
  two_product(a, b, p.hi, p.lo);
  return p;
}

// Their AccurateDWPlusDW: relative error at most 3u^2 + 13u^3 (u = 2^-53), cancellation included.
DoubleWord dw_add(DoubleWord x, DoubleWord y) {
  double sh, sl, th, tl, vh, vl, zh, zl;
  two_sum(x.hi, y.hi, sh, sl);
  two_sum(x.lo, y.lo, th, tl);
  fast_two_sum(sh, sl + th, vh, vl);
  fast_two_sum(vh, tl + vl, zh, zl);
  return {zh, zl};
}

DoubleWord negated(DoubleWord x) { return {-x.hi, -x.lo}; }

// Their DWTimesDW1: relative error at most 7u^2.
DoubleWord dw_multiply(DoubleWord x, DoubleWord y) {
  double ch, cl1, zh, zl;
  two_product(x.hi, y.hi, ch, cl1);
  const double cl2 = x.hi * y.lo + x.lo * y.hi;
  fast_two_sum(ch, cl1 + cl2, zh, zl);
  return {zh, zl};
}

// Stage B's determinant of the exact differences in double-word arithmetic. Each minor and lift
// is within 3.1u^2 of its exact value, each lift * minor within 14u^2 and the two final sums add
// 3.1u^2 of the sum of the terms' magnitudes each, so the error is below 21u^2 times the
// permanent; 128u^2 leaves room for the permanent's own rounding and for reading the sign off
// hi. Rounded cocircular points (the vertices of a polygonal hole) miss zero by about u times the
// permanent, so this decides nearly all of them at a tenth of the cost of expansions.
constexpr double kIncircleDoubleWord = 128.0 * kEpsilon * kEpsilon;

bool incircle_double_word(const double (&d)[6], double permanent, double& det) {
  const double adx = d[0], ady = d[1], bdx = d[2], bdy = d[3], cdx = d[4], cdy = d[5];
  const auto minor = [](double p, double q, double r, double s) {
    return dw_add(exact_product(p, q), negated(exact_product(r, s)));
  };
  const auto lift = [](double x, double y) { return dw_add(exact_product(x, x), exact_product(y, y)); };
  const DoubleWord a_term = dw_multiply(lift(adx, ady), minor(bdx, cdy, cdx, bdy));
  const DoubleWord b_term = dw_multiply(lift(bdx, bdy), minor(cdx, ady, adx, cdy));
  const DoubleWord c_term = dw_multiply(lift(cdx, cdy), minor(adx, bdy, bdx, ady));
  det = dw_add(dw_add(a_term, b_term), c_term).hi;
  return std::fabs(det) > kIncircleDoubleWord * permanent;
}

}  // namespace

double Predicates::orient2d_adapt(const Point& a, const Point& b, const Point& c, double detsum) {
  // Both products with a zero factor (equal coordinates: axis-parallel collinear points) are
  // exactly zero; the filter passes these on only because a zero permanent cannot rule out
  // underflow.
  if (detsum == 0.0 && (a.x == c.x || b.y == c.y) && (a.y == c.y || b.x == c.x)) return 0.0;
  ++counters.orient_adaptive;
  const Point points[3] = {a, b, c};
  if (!exact_integer::coordinates_within(points, 3, kOrientLow, kOrientHigh)) {
    ++counters.orient_exact;
    return exact_integer::orient2d_sign(a, b, c);
  }
  const double acx = a.x - c.x, bcx = b.x - c.x;
  const double acy = a.y - c.y, bcy = b.y - c.y;

  double stage_b[4];
  const int stage_b_len = difference_of_products(acx, bcy, acy, bcx, stage_b);
  double det = signed_estimate(stage_b, stage_b_len);
  if (det >= kOrientB * detsum || -det >= kOrientB * detsum) return det;

  const double acx_tail = two_diff_tail(a.x, c.x, acx), bcx_tail = two_diff_tail(b.x, c.x, bcx);
  const double acy_tail = two_diff_tail(a.y, c.y, acy), bcy_tail = two_diff_tail(b.y, c.y, bcy);
  if (acx_tail == 0.0 && acy_tail == 0.0 && bcx_tail == 0.0 && bcy_tail == 0.0) return det;

  const double bound = kOrientC * detsum + kResultBound * std::fabs(det);
  det += (acx * bcy_tail + bcy * acx_tail) - (acy * bcx_tail + bcx * acy_tail);
  if (det >= bound || -det >= bound) return det;

  ++counters.orient_exact;
  double exact_det[exact::kOrientMax];
  const int n = exact::orient2d(a, b, c, exact_det);
  return signed_estimate(exact_det, n);
}

double Predicates::incircle_adapt(const Point& a, const Point& b, const Point& c, const Point& d,
                                  double permanent) {
  ++counters.incircle_adaptive;
  if (rectangle_corners(a, b, c, d)) return 0.0;
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const bool exact_differences =
      two_diff_tail(a.x, d.x, adx) == 0.0 && two_diff_tail(a.y, d.y, ady) == 0.0 &&
      two_diff_tail(b.x, d.x, bdx) == 0.0 && two_diff_tail(b.y, d.y, bdy) == 0.0 &&
      two_diff_tail(c.x, d.x, cdx) == 0.0 && two_diff_tail(c.y, d.y, cdy) == 0.0;
  ScaledDifferences scaled;
  const bool scaled_ok = exact_differences && scale_to_integers({adx, ady, bdx, bdy, cdx, cdy}, scaled);
  // Exactly cocircular lattice points first: no filter can decide a zero. With the differences
  // within 12 bits, every product and sum of the plain determinant is an integer multiple of a
  // power of two below 2^53 (12 monomials of 4 factors: 4 * 12 + 4 bits), so no operation rounds:
  // stage B's usual case on a coarse dyadic grid, where refinement meets such quadruples by the
  // million.
  if (scaled_ok && scaled.width <= 12 && scaled.fits_doubles())
    return plain_incircle(adx, ady, bdx, bdy, cdx, cdy).det;
  if constexpr (kWideLongDouble) {
    double extended = 0.0;
    if (extended_precision_active() && incircle_extended(a, b, c, d, extended)) return extended;
  }
  if (scaled_ok) {
    double quick = 0.0;
    if (scaled.fits_doubles() && incircle_double_word({adx, ady, bdx, bdy, cdx, cdy}, permanent, quick))
      return quick;
    return incircle_in_integers(scaled);
  }

  const Point points[4] = {a, b, c, d};
  if (!exact_integer::coordinates_within(points, 4, kIncircleLow, kIncircleHigh)) {
    ++counters.incircle_exact;
    return exact_integer::incircle_sign(a, b, c, d);
  }
  double bc[4], ca[4], ab[4];
  const int bcn = difference_of_products(bdx, cdy, cdx, bdy, bc);
  const int can = difference_of_products(cdx, ady, adx, cdy, ca);
  const int abn = difference_of_products(adx, bdy, bdx, ady, ab);
  double a_term[32], b_term[32], c_term[32], ab_terms[64], stage_b[96];
  const int an = lifted_minor(bc, bcn, adx, ady, a_term);
  const int bn = lifted_minor(ca, can, bdx, bdy, b_term);
  const int cn = lifted_minor(ab, abn, cdx, cdy, c_term);
  const int abtn = sum(a_term, an, b_term, bn, ab_terms);
  const int stage_b_len = sum(ab_terms, abtn, c_term, cn, stage_b);
  double det = signed_estimate(stage_b, stage_b_len);
  if (decided(det, kIncircleB * permanent)) return det;

  const double adx_tail = two_diff_tail(a.x, d.x, adx), ady_tail = two_diff_tail(a.y, d.y, ady);
  const double bdx_tail = two_diff_tail(b.x, d.x, bdx), bdy_tail = two_diff_tail(b.y, d.y, bdy);
  const double cdx_tail = two_diff_tail(c.x, d.x, cdx), cdy_tail = two_diff_tail(c.y, d.y, cdy);
  if (adx_tail == 0.0 && ady_tail == 0.0 && bdx_tail == 0.0 && bdy_tail == 0.0 &&
      cdx_tail == 0.0 && cdy_tail == 0.0) {
    return det;
  }

  const double bound = kIncircleC * permanent + kResultBound * std::fabs(det);
  det += first_order(adx, ady, adx_tail, ady_tail, bdx * cdy - bdy * cdx,
                     (bdx * cdy_tail + cdy * bdx_tail) - (bdy * cdx_tail + cdx * bdy_tail)) +
         first_order(bdx, bdy, bdx_tail, bdy_tail, cdx * ady - cdy * adx,
                     (cdx * ady_tail + ady * cdx_tail) - (cdy * adx_tail + adx * cdy_tail)) +
         first_order(cdx, cdy, cdx_tail, cdy_tail, adx * bdy - ady * bdx,
                     (adx * bdy_tail + bdy * adx_tail) - (ady * bdx_tail + bdx * ady_tail));
  if (decided(det, bound)) return det;

  ++counters.incircle_exact;
  double exact_det[exact::kIncircleMax];
  const int n = exact::incircle(a, b, c, d, exact_det);
  return signed_estimate(exact_det, n);
}

}  // namespace deltri
