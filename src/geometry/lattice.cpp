#include "geometry/lattice.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

#include "geometry/constructions.h"

namespace deltri {
namespace {

// The double `k` steps from x (negative: downwards).
double step(double x, int k) {
  const double towards = k < 0 ? -HUGE_VAL : HUGE_VAL;
  for (int i = 0; i < std::abs(k); ++i) x = std::nextafter(x, towards);
  return x;
}

// The doubles within `radius` of x, x itself included, if there are at most `limit` on each side.
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

double smallest_angle_sine2(const Point& a, const Point& b, const Point& c) {
  const double abx = b.x - a.x, aby = b.y - a.y, acx = c.x - a.x, acy = c.y - a.y;
  const double bcx = c.x - b.x, bcy = c.y - b.y;
  const double twice_area = abx * acy - aby * acx;
  if (!(twice_area > 0.0)) return 0.0;
  double l[3] = {abx * abx + aby * aby, bcx * bcx + bcy * bcy, acx * acx + acy * acy};
  std::sort(l, l + 3);
  return twice_area * twice_area / (l[1] * l[2]);
}

bool hopeless_edge(const Point& p, const Point& q, double sin2_theta) {
  if (!(sin2_theta > 0.0)) return false;
  const double length = std::sqrt(squared_distance(p, q));
  const double radius = length * (1.0 / std::sqrt(sin2_theta) + 0.5);
  const Point mid{p.x + 0.5 * (q.x - p.x), p.y + 0.5 * (q.y - p.y)};
  std::vector<double> xs, ys;
  if (!doubles_within(mid.x, radius, kHopelessSteps, xs) || !doubles_within(mid.y, radius, kHopelessSteps, ys))
    return false;
  for (double x : xs)
    for (double y : ys)
      if (smallest_angle_sine2(p, q, Point{x, y}) >= sin2_theta) return false;
  return true;
}

}  // namespace deltri
