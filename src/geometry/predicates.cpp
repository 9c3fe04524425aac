// The adaptive stages of orient2d and incircle (Shewchuk 1997, sections 4.2-4.4).
//
// Stage B evaluates the determinant exactly, but from the rounded coordinate differences; if those
// differences were themselves exact (the common case for nearby points) that is the true answer.
// Stage C adds the first-order effect of the differences' roundoff in floating point. Stage D
// evaluates the determinant exactly from the input coordinates. Each stage stops as soon as its
// error bound proves the sign.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

#include "geometry/expansion.h"
#include "geometry/exact_determinants.h"
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

bool decided(double det, double bound) { return det > bound || -det > bound; }

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

// Points of a coarse lattice (grids, integer coordinates) meet the adaptive stage in great numbers
// as cocircular quadruples, whose determinant is exactly zero; true means that it is, which stage B
// would also find, at several times the cost. If every difference is an integer multiple of a power
// of two g and at most 4096 g in magnitude, every product and sum of the plain evaluation is an
// integer multiple of g^4 below 2^52 g^4, so that evaluation is exact. The magnitude limits keep
// g^4 and the scaling by 1/g clear of underflow and overflow.
bool exactly_cocircular(const double (&d)[6]) {
  double m = 0.0;
  for (double v : d) m = std::max(m, std::fabs(v));
  if (m == 0.0) return true;
  if (!(m >= 0x1p-200 && m <= 0x1p200)) return false;
  // m < 2^e with e from m's exponent field; 1/g = 2^(12 - e).
  const int e = static_cast<int>(std::bit_cast<std::uint64_t>(m) >> 52) - 1022;
  const double to_units = std::bit_cast<double>(static_cast<std::uint64_t>(12 - e + 1023) << 52);
  for (double v : d) {
    const double u = v * to_units;  // |u| < 4096: the conversion below cannot overflow
    if (u != static_cast<double>(static_cast<std::int32_t>(u))) return false;
  }
  const auto [adx, ady, bdx, bdy, cdx, cdy] = d;
  const double det = (adx * adx + ady * ady) * (bdx * cdy - cdx * bdy) +
                     (bdx * bdx + bdy * bdy) * (cdx * ady - adx * cdy) +
                     (cdx * cdx + cdy * cdy) * (adx * bdy - bdx * ady);
  return det == 0.0;
}

}  // namespace

double Predicates::orient2d_adapt(const Point& a, const Point& b, const Point& c, double detsum) {
  ++counters.orient_adaptive;
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
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const bool exact_differences =
      two_diff_tail(a.x, d.x, adx) == 0.0 && two_diff_tail(a.y, d.y, ady) == 0.0 &&
      two_diff_tail(b.x, d.x, bdx) == 0.0 && two_diff_tail(b.y, d.y, bdy) == 0.0 &&
      two_diff_tail(c.x, d.x, cdx) == 0.0 && two_diff_tail(c.y, d.y, cdy) == 0.0;
  if (exact_differences && exactly_cocircular({adx, ady, bdx, bdy, cdx, cdy})) return 0.0;

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
