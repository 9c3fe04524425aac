// Adaptive exact predicates after Shewchuk, "Adaptive Precision Floating-Point Arithmetic and
// Fast Robust Geometric Predicates" (1997), written from the published method.
//
// Each predicate first evaluates the determinant in plain floating point and accepts its sign when
// the magnitude exceeds a proven error bound (the filter). Otherwise it recomputes with expansion
// arithmetic, first cheaply (the adaptive stage, reusing the exact differences when the input
// differences were exact), and if that is still not conclusive, to full precision (the exact stage).
// Before that, incircle tries cheaper ways to the same exact sign (predicates.cpp): plain doubles
// when the differences are exact and span at most 12 bits (dyadic grids, where refinement meets
// exactly cocircular points all the time), the filter again in long double (rounded cocircular
// points), and with exact differences double-word arithmetic with a proven error bound and 256-bit
// integers up to 62 bits (exactly cocircular points such as a symmetric polygon's).
// The sign returned is always the sign of the exact determinant of the given doubles.
//
// Every finite double, subnormals included: the expansion stages are exact only while every product
// and its roundoff stay clear of overflow and underflow, which holds when each coordinate is zero or
// has magnitude in [2^-400, 2^500] for orient2d and [2^-170, 2^250] for incircle. A test with a
// coordinate outside that range that the filter (guarded against underflow, see bounds) cannot
// decide goes to exact_integer.h, which evaluates the determinant in integers and cannot underflow
// or overflow. Build without -ffast-math and without -ffp-contract=fast (see expansion.h).
//
// There is no global state: a Predicates object carries its own counters, so each thread owns one
// and the CLI sums them for -V.
#pragma once

#include <cmath>
#include <cstdint>

#include "geometry/point.h"

namespace deltri {

struct PredicateCounters {
  std::uint64_t orient_calls = 0;     // every orient2d call
  std::uint64_t orient_adaptive = 0;  // calls the filter could not decide
  std::uint64_t orient_exact = 0;     // calls that needed the full exact stage
  std::uint64_t incircle_calls = 0;
  std::uint64_t incircle_adaptive = 0;
  std::uint64_t incircle_exact = 0;

  void add(const PredicateCounters& o) {
    orient_calls += o.orient_calls;
    orient_adaptive += o.orient_adaptive;
    orient_exact += o.orient_exact;
    incircle_calls += o.incircle_calls;
    incircle_adaptive += o.incircle_adaptive;
    incircle_exact += o.incircle_exact;
  }
};

// Keeps a block's predicate calls out of the counts (-V): checks made only in builds with invariant
// checks must leave the counters as every build reports them.
class Predicates;
class UncountedCalls {
 public:
  explicit UncountedCalls(Predicates& pred);
  ~UncountedCalls();
  UncountedCalls(const UncountedCalls&) = delete;
  UncountedCalls& operator=(const UncountedCalls&) = delete;

 private:
  Predicates& pred_;
  PredicateCounters saved_;
};

// Error bounds of the filters (Shewchuk 1997, section 4); epsilon = 2^-53.
namespace bounds {
inline constexpr double kEpsilon = 1.1102230246251565e-16;
inline constexpr double kOrientA = (3.0 + 16.0 * kEpsilon) * kEpsilon;
inline constexpr double kIncircleA = (10.0 + 96.0 * kEpsilon) * kEpsilon;
// The filters' analysis assumes no product underflows or overflows. In orient2d (and the dot
// products of the diametral tests) a product that underflows is off by at most 2^-1075 and is
// not multiplied again, so while the permanent (detsum) is at least kOrientMin those absolute
// errors are below 2^-170 of it, far inside the second-order slack of the bound (16 epsilon^2);
// below it the filter does not decide. Overflow makes the permanent infinite or NaN, which fails
// the comparisons. incircle multiplies products again, so it checks its differences instead
// (Predicates::filter_safe).
inline constexpr double kOrientMin = 0x1p-900;
inline constexpr double kFiniteMax = 0x1.fffffffffffffp+1023;
}  // namespace bounds

// incircle's determinant evaluated plainly in R from the six coordinate differences (a - d, b - d,
// c - d), with its permanent (the sum of its terms' magnitudes, which scales its error bound):
// in double for the filter, in long double for the first adaptive try, and in double where the
// differences make that evaluation exact.
template <class R>
struct PlainIncircle {
  R det, permanent;
};

template <class R>
inline PlainIncircle<R> plain_incircle(R adx, R ady, R bdx, R bdy, R cdx, R cdy) {
  const R bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const R alift = adx * adx + ady * ady;
  const R cdxady = cdx * ady, adxcdy = adx * cdy;
  const R blift = bdx * bdx + bdy * bdy;
  const R adxbdy = adx * bdy, bdxady = bdx * ady;
  const R clift = cdx * cdx + cdy * cdy;
  return {alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady),
          (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift + (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
              (std::fabs(adxbdy) + std::fabs(bdxady)) * clift};
}

class Predicates {
 public:
  // Positive if a, b, c are in counter-clockwise order, negative if clockwise, zero if collinear.
  // The magnitude is meaningless except for its sign (it approximates twice the signed area).
  double orient2d(const Point& a, const Point& b, const Point& c) {
    ++counters.orient_calls;
    const double left = (a.x - c.x) * (b.y - c.y);
    const double right = (a.y - c.y) * (b.x - c.x);
    const double det = left - right;
    // Branch-free form of the paper's sign cases: when left and right differ in sign (or one is
    // zero) |det| is exactly the rounded detsum and always passes, so only the same-sign case can
    // reach the adaptive stage. Random signs would otherwise cost branch mispredictions.
    const double detsum = std::fabs(left) + std::fabs(right);
    if (std::fabs(det) >= bounds::kOrientA * detsum && detsum >= bounds::kOrientMin && detsum <= bounds::kFiniteMax)
      return det;
    return orient2d_adapt(a, b, c, detsum);
  }

  // Positive if d lies inside the circle through a, b, c (given counter-clockwise), negative if
  // outside, zero if the four points are cocircular.
  double incircle(const Point& a, const Point& b, const Point& c, const Point& d) {
    return incircle_filtered<false>(a, b, c, d);
  }

  // incircle with its ties broken by a symbolic perturbation, so that the Delaunay triangulation
  // is unique and every builder (divide and conquer, -F, -i) makes the same one. Each point's lift
  // x^2 + y^2 is lowered by epsilon^rank, rank 1, 2, ... in lexicographic (x, y) order (an order of
  // the coordinates alone, not of the input), for an infinitesimal epsilon > 0. Where the exact
  // determinant is nonzero that changes nothing and this is incircle; where it is zero the sign is
  // that of the highest-priority term (symbolic_perturbation.cpp). Zero only when all four points
  // are collinear; never for a, b, c counter-clockwise and d distinct from them. The four points
  // must be distinct. On a square the diagonal kept is the one through its lower left corner.
  // The tie rule sits behind the adaptive stage (only a determinant the filter cannot decide can
  // be zero), so a caller pays nothing for it on general-position input.
  double incircle_perturbed(const Point& a, const Point& b, const Point& c, const Point& d) {
    return incircle_filtered<true>(a, b, c, d);
  }

  PredicateCounters counters;

 private:
  template <bool kBreakTies>
  double incircle_filtered(const Point& a, const Point& b, const Point& c, const Point& d) {
    ++counters.incircle_calls;
    const double adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y, cdx = c.x - d.x, cdy = c.y - d.y;
    const PlainIncircle<double> plain = plain_incircle(adx, ady, bdx, bdy, cdx, cdy);
    // Unlike orient2d's, a product that underflows here is multiplied again (a minor of 1e-333
    // lost to underflow, times a lift of 1e265), so no test of the permanent can bound the damage:
    // the filter decides only when no product can underflow or overflow at all.
    if (std::fabs(plain.det) > bounds::kIncircleA * plain.permanent && filter_safe(adx) && filter_safe(ady) &&
        filter_safe(bdx) && filter_safe(bdy) && filter_safe(cdx) && filter_safe(cdy))
      return plain.det;
    if constexpr (kBreakTies) return incircle_adapt_perturbed(a, b, c, d, plain.permanent);
    return incircle_adapt(a, b, c, d, plain.permanent);
  }

  // A coordinate difference with which incircle's plain evaluation (products of up to four
  // differences, sums of six) neither underflows nor overflows.
  static bool filter_safe(double v) {
    const double m = std::fabs(v);
    return m == 0.0 || (m >= 0x1p-250 && m <= 0x1p250);
  }

  double orient2d_adapt(const Point& a, const Point& b, const Point& c, double detsum);
  double incircle_adapt(const Point& a, const Point& b, const Point& c, const Point& d,
                        double permanent);
  // incircle_adapt, and where it finds zero the sign of the perturbation's leading term.
  double incircle_adapt_perturbed(const Point& a, const Point& b, const Point& c, const Point& d,
                                  double permanent);
};

inline UncountedCalls::UncountedCalls(Predicates& pred) : pred_(pred), saved_(pred.counters) {}
inline UncountedCalls::~UncountedCalls() { pred_.counters = saved_; }

}  // namespace deltri
