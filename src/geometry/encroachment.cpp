#include "geometry/encroachment.h"

#include <algorithm>
#include <cmath>

#include "geometry/exact_determinants.h"
#include "geometry/exact_integer.h"
#include "geometry/expansion.h"
#include "geometry/predicates.h"

namespace deltri {
namespace {

constexpr double kRadiansPerDegree = 3.14159265358979323846 / 180.0;

// cos(2 theta) written as sin(90 - 2 theta) so that theta = 45 yields exactly zero, which makes the
// lens test collapse to the exact diametral-circle test.
double cos_double_angle(double theta_degrees) {
  return std::sin((90.0 - 2.0 * theta_degrees) * kRadiansPerDegree);
}

}  // namespace

bool in_diametral_circle(const Point& a, const Point& b, const Point& p) {
  const double x_part = (a.x - p.x) * (b.x - p.x);
  const double y_part = (a.y - p.y) * (b.y - p.y);
  const double dot = x_part + y_part;
  // Products below 2^-900 may have underflowed and lost their sign or their roundoff; with every
  // coordinate in [2^-400, 2^500] that cannot happen (only an exact zero difference gives a zero
  // product), otherwise the test is done in integers.
  const double permanent = std::fabs(x_part) + std::fabs(y_part);
  if (!(permanent >= bounds::kOrientMin && permanent <= bounds::kFiniteMax)) {
    const Point points[3] = {a, b, p};
    if (!exact_integer::coordinates_within(points, 3, -400, 500)) return exact_integer::dot_sign(a, b, p) < 0;
  }
  // Rounding never flips the sign of a difference or a product (barring underflow), so terms of
  // equal sign decide alone; otherwise the orient2d filter bound applies to this sum unchanged.
  if ((x_part <= 0.0) == (y_part <= 0.0) || x_part == 0.0 || y_part == 0.0) return dot < 0.0;
  const double bound = bounds::kOrientA * (std::fabs(x_part) + std::fabs(y_part));
  if (dot > bound || -dot > bound) return dot < 0.0;
  double exact_dot[exact::kDotMax];
  const int n = exact::diametral_dot(a, b, p, exact_dot);
  return expansion::sign(exact_dot, n) < 0;
}

bool in_diametral_lens(const Point& a, const Point& b, const Point& p, double min_angle_degrees) {
  // The angle apb exceeds 180 - 2 theta iff cos(apb) < -cos(2 theta), i.e.
  // dot < -c |pa| |pb| with c = cos(2 theta); squaring avoids the square roots.
  if (!(min_angle_degrees > 0.0)) return false;
  const double c = cos_double_angle(std::min(min_angle_degrees, 90.0));
  const bool obtuse = in_diametral_circle(a, b, p);
  if (c == 0.0) return obtuse;
  const double pa2 = (a.x - p.x) * (a.x - p.x) + (a.y - p.y) * (a.y - p.y);
  const double pb2 = (b.x - p.x) * (b.x - p.x) + (b.y - p.y) * (b.y - p.y);
  const double dot = (a.x - p.x) * (b.x - p.x) + (a.y - p.y) * (b.y - p.y);
  const double dot2 = dot * dot, limit = c * c * (pa2 * pb2);  // symmetric in a and b
  // Narrow lens (theta < 45): obtuse and steeper than the bound. Wide lens (theta > 45): obtuse, or
  // acute but not as sharp as the bound.
  if (c > 0.0) return obtuse && dot2 > limit;
  return obtuse || dot2 < limit;
}

}  // namespace deltri
