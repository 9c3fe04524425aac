#include "refine/concentric_shells.h"

#include <cmath>

namespace deltri {

double shell_radius(double length) {
  double radius = std::exp2(std::ceil(std::log2(length / 3.0)));
  // log2 rounds; correct by one octave if it landed outside the interval.
  if (radius >= 2.0 * length / 3.0) radius *= 0.5;
  if (radius < length / 3.0) radius *= 2.0;
  return radius;
}

Point shell_split_point(const Point& a, const Point& b, bool a_is_apex, bool b_is_apex) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  // Ends near the opposite ends of the double range overflow dx: halve first there (exact for
  // such large values).
  if (!std::isfinite(dx) || !std::isfinite(dy)) return Point{0.5 * a.x + 0.5 * b.x, 0.5 * a.y + 0.5 * b.y};
  if (!a_is_apex && !b_is_apex) return Point{a.x + 0.5 * dx, a.y + 0.5 * dy};
  const double length = std::sqrt(dx * dx + dy * dy);
  const double t = shell_radius(length) / length;
  if (a_is_apex) return Point{a.x + t * dx, a.y + t * dy};
  return Point{b.x - t * dx, b.y - t * dy};
}

}  // namespace deltri
