#include "geometry/lattice.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace deltri {
namespace {

// The double `k` steps from x (negative: downwards).
double step(double x, int k) {
  const double towards = k < 0 ? -HUGE_VAL : HUGE_VAL;
  for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, towards);
  return x;
}

}  // namespace

void lattice_neighbourhood(const Point& c, int steps, std::vector<Point>& out) {
  double xs[2 * 16 + 1], ys[2 * 16 + 1];
  steps = std::clamp(steps, 0, 16);
  for (int k = -steps; k <= steps; ++k) {
    xs[k + steps] = step(c.x, k);
    ys[k + steps] = step(c.y, k);
  }
  for (int ring = 0; ring <= steps; ++ring)
    for (int i = -ring; i <= ring; ++i)
      for (int j = -ring; j <= ring; ++j)
        if (std::max(std::abs(i), std::abs(j)) == ring) out.push_back({xs[i + steps], ys[j + steps]});
}

bool doubles_within(double x, double radius, int limit, std::vector<double>& out) {
  out.clear();
  out.push_back(x);
  for (const double towards : {-HUGE_VAL, HUGE_VAL}) {
    double y = x;
    for (int i = 0;; ++i) {
      y = std::nextafter(y, towards);
      if (!(std::fabs(y - x) <= radius)) break;
      if (i == limit) return false;
      out.push_back(y);
    }
  }
  return true;
}

}  // namespace deltri
