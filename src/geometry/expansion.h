// Exact floating-point expansion arithmetic (Dekker 1971, Priest 1991, Shewchuk 1997 sections 2-3),
// written from the published mathematics.
//
// An expansion is an array of doubles ordered by increasing magnitude whose exact (unrounded) sum is
// the number it stands for. The components do not overlap bitwise, so the last one dominates the
// rest and carries the sign of the whole. An empty expansion (length 0) is zero; the routines drop
// zero components as they go, which keeps the arrays short in the common near-degenerate cases.
//
// Everything here is exact under IEEE-754 binary64 with round-to-nearest-even, provided nothing
// overflows and no product's rounding error falls below the subnormal range (see predicates.h for
// input ranges that guarantee this). The error-free transformations rely on each operation being
// rounded separately: do not compile with -ffp-contract=fast (g++ in ISO mode, -std=c++20, keeps
// contraction off) or -ffast-math.
#pragma once

#include <cmath>

namespace deltri::expansion {

// x = fl(a + b) and y = (a + b) - x exactly. Only valid when |a| >= |b| or a == 0; cheaper than
// two_sum because it need not find out which operand lost bits.
inline void fast_two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  y = b - (x - a);
}

// Knuth's branch-free sum: recovers the bits of both operands that the rounded sum discarded.
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double b_part = x - a;
  const double a_part = x - b_part;
  y = (a - a_part) + (b - b_part);
}

// The roundoff of x = fl(a - b), given x, so that a - b == x + tail exactly.
inline double two_diff_tail(double a, double b, double x) {
  const double b_part = a - x;
  const double a_part = x + b_part;
  return (a - a_part) + (b_part - b);
}

inline void two_diff(double a, double b, double& x, double& y) {
  x = a - b;
  y = two_diff_tail(a, b, x);
}

#if defined(__FP_FAST_FMA)
// With a hardware fused multiply-add the product's roundoff is one exact operation away.
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);
}
#else
// Dekker's split: hi carries the top 26 significant bits of a and lo the rest, so that products of
// halves are exact in double. Overflows for |a| above about 2^996.
inline void split(double a, double& hi, double& lo) {
  constexpr double kSplitter = 134217729.0;  // 2^27 + 1
  const double scaled = kSplitter * a;
  const double excess = scaled - a;
  hi = scaled - excess;
  lo = a - hi;
}

// x = fl(a * b) and y = a * b - x exactly, from the four exact half-products (Dekker).
inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  double a_hi, a_lo, b_hi, b_lo;
  split(a, a_hi, a_lo);
  split(b, b_hi, b_lo);
  const double err1 = x - a_hi * b_hi;
  const double err2 = err1 - a_lo * b_hi;
  const double err3 = err2 - a_hi * b_lo;
  y = a_lo * b_lo - err3;
}
#endif

// Capacity rules: each routine writes at most the stated number of components into h, which must not
// alias its inputs. All return the number of components written.

// h = e + b; at most elen + 1 components.
int grow(const double* e, int elen, double b, double* h);

// h = e * b; at most 2 * elen components.
int scale(const double* e, int elen, double b, double* h);

// h = e + f; at most elen + flen components.
int sum(const double* e, int elen, const double* f, int flen, double* h);

// h = e * f; at most 2 * elen * flen components. scratch must hold 2 * elen * (flen + 1) doubles.
int multiply(const double* e, int elen, const double* f, int flen, double* h, double* scratch);

// e = -e in place.
void negate(double* e, int elen);

// h = a * b - c * d exactly; at most 4 components.
int difference_of_products(double a, double b, double c, double d, double* h);

// An approximation of the value, accurate to a few ulps; its sign may be wrong only in contrived
// cases, so callers that need the sign use signed_estimate.
double estimate(const double* e, int elen);

// The estimate, but replaced by the dominant component if rounding made their signs disagree, so
// its sign is always the exact sign of the expansion.
double signed_estimate(const double* e, int elen);

// -1, 0 or +1: the sign of the dominant (last) component, which is the sign of the exact value.
inline int sign(const double* e, int elen) {
  if (elen == 0) return 0;
  return e[elen - 1] > 0.0 ? 1 : (e[elen - 1] < 0.0 ? -1 : 0);
}

}  // namespace deltri::expansion
