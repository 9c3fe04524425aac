#include "refine/exact_dot.h"

#include <array>
#include <cmath>

#include "geometry/exact_integer.h"
#include "geometry/predicates.h"

namespace deltri {
namespace {

// Knuth's two-sum: a + b == sum + err exactly.
void two_sum(double a, double b, double& sum, double& err) {
  sum = a + b;
  const double bv = sum - a;
  const double av = sum - bv;
  err = (a - av) + (b - bv);
}

// Adds b to the nonoverlapping expansion e (increasing magnitude), keeping it exact; zero
// components are dropped so the most significant component carries the sign.
int grow(std::array<double, 32>& e, int n, double b) {
  int out = 0;
  double q = b;
  for (int i = 0; i < n; ++i) {
    double sum, err;
    two_sum(q, e[i], sum, err);
    if (err != 0.0) e[out++] = err;
    q = sum;
  }
  if (q != 0.0) e[out++] = q;
  return out;
}

int exact_sign(double xx, double xy, double yx, double yy, double wx, double wy) {
  // (xx - wx)(yx - wx) + (xy - wy)(yy - wy), expanded into eight products, each split exactly
  // into a rounded product and its fma residual.
  const double f[8][2] = {{xx, yx}, {-xx, wx}, {-wx, yx}, {wx, wx},
                          {xy, yy}, {-xy, wy}, {-wy, yy}, {wy, wy}};
  std::array<double, 32> e{};
  int n = 0;
  for (const auto& p : f) {
    const double prod = p[0] * p[1];
    n = grow(e, n, std::fma(p[0], p[1], -prod));
    n = grow(e, n, prod);
  }
  if (n == 0) return 0;
  return e[n - 1] > 0.0 ? 1 : -1;
}

}  // namespace

int dot_sign(const Point& x, const Point& y, const Point& w) {
  const double ax = x.x - w.x, ay = x.y - w.y, bx = y.x - w.x, by = y.y - w.y;
  const double dot = ax * bx + ay * by;
  // Each difference and product carries a relative error of at most one unit roundoff, the sum
  // one more; 8 epsilon of the permanent is a safe filter.
  const double permanent = std::fabs(ax * bx) + std::fabs(ay * by);
  const double bound = 8.0 * 1.1102230246251565e-16 * permanent;
  // A permanent below 2^-900 may hide underflowed products (and exact_sign's products of the raw
  // coordinates underflow or overflow outside [2^-400, 2^500]): then the sign comes from integers.
  const bool filter_safe = permanent >= bounds::kOrientMin && permanent <= bounds::kFiniteMax;
  if (filter_safe && dot > bound) return 1;
  if (filter_safe && dot < -bound) return -1;
  const Point points[3] = {x, y, w};
  if (!exact_integer::coordinates_within(points, 3, -400, 500)) return exact_integer::dot_sign(x, y, w);
  return exact_sign(x.x, x.y, y.x, y.y, w.x, w.y);
}

}  // namespace deltri
