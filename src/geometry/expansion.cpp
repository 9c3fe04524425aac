#include "geometry/expansion.h"

#include <algorithm>

namespace deltri::expansion {

int grow(const double* e, int elen, double b, double* h) {
  // Ripple b upward through the components; each two_sum leaves behind the bits that no longer fit
  // in the running sum, and those leftovers are smaller than every later component.
  int n = 0;
  double running = b;
  for (int i = 0; i < elen; ++i) {
    double low;
    two_sum(running, e[i], running, low);
    if (low != 0.0) h[n++] = low;
  }
  if (running != 0.0) h[n++] = running;
  return n;
}

int scale(const double* e, int elen, double b, double* h) {
  if (elen == 0) return 0;
  int n = 0;
  double running, low;
  two_product(e[0], b, running, low);
  if (low != 0.0) h[n++] = low;
  for (int i = 1; i < elen; ++i) {
    // The product's low half can overlap the running sum and is folded in exactly; the high half is
    // at least as large as everything accumulated so far, which makes fast_two_sum valid.
    double product_hi, product_lo, partial;
    two_product(e[i], b, product_hi, product_lo);
    two_sum(running, product_lo, partial, low);
    if (low != 0.0) h[n++] = low;
    fast_two_sum(product_hi, partial, running, low);
    if (low != 0.0) h[n++] = low;
  }
  if (running != 0.0) h[n++] = running;
  return n;
}

int sum(const double* e, int elen, const double* f, int flen, double* h) {
  // Merge both by magnitude, then sweep once with two_sum: with round-to-nearest-even and inputs
  // produced by these routines the result again does not overlap (Shewchuk 1997, theorem 13).
  int i = 0, j = 0, n = 0;
  auto next_smallest = [&]() {
    if (j >= flen || (i < elen && std::fabs(e[i]) < std::fabs(f[j]))) return e[i++];
    return f[j++];
  };
  const int total = elen + flen;
  if (total == 0) return 0;
  double running = next_smallest();
  for (int k = 1; k < total; ++k) {
    double low;
    two_sum(running, next_smallest(), running, low);
    if (low != 0.0) h[n++] = low;
  }
  if (running != 0.0) h[n++] = running;
  return n;
}

int multiply(const double* e, int elen, const double* f, int flen, double* h, double* scratch) {
  // Distribute over f's components, accumulating in two buffers (h and scratch) used alternately.
  double* term = scratch + 2 * elen * flen;
  double* accumulated = h;
  double* spare = scratch;
  int n = 0;
  for (int j = 0; j < flen; ++j) {
    const int term_len = scale(e, elen, f[j], term);
    n = sum(accumulated, n, term, term_len, spare);
    std::swap(accumulated, spare);
  }
  if (accumulated != h) std::copy(accumulated, accumulated + n, h);
  return n;
}

void negate(double* e, int elen) {
  for (int i = 0; i < elen; ++i) e[i] = -e[i];
}

int difference_of_products(double a, double b, double c, double d, double* h) {
  double left[2], right[2];
  two_product(a, b, left[1], left[0]);
  two_product(c, d, right[1], right[0]);
  double partial[3];
  int n = grow(left, 2, -right[0], partial);
  return grow(partial, n, -right[1], h);
}

double estimate(const double* e, int elen) {
  double total = 0.0;
  for (int i = 0; i < elen; ++i) total += e[i];
  return total;
}

double signed_estimate(const double* e, int elen) {
  const double approx = estimate(e, elen);
  const int exact_sign = sign(e, elen);
  const int approx_sign = approx > 0.0 ? 1 : (approx < 0.0 ? -1 : 0);
  return approx_sign == exact_sign ? approx : e[elen - 1];
}

}  // namespace deltri::expansion
