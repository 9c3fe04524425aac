#include "geometry/encroachment.h"

#include <cmath>
#include <numbers>

#include "geometry/exact_determinants.h"
#include "geometry/exact_integer.h"
#include "geometry/expansion.h"

namespace deltri {

int diametral_dot_sign(const Point& a, const Point& b, const Point& p) {
  const double x_part = (a.x - p.x) * (b.x - p.x);
  const double y_part = (a.y - p.y) * (b.y - p.y);
  const double dot = x_part + y_part;
  // Products below 2^-900 may have underflowed and lost their sign or their roundoff; with every
  // coordinate in [2^-400, 2^500] that cannot happen (only an exact zero difference gives a zero
  // product), otherwise the test is done in integers.
  const double permanent = std::fabs(x_part) + std::fabs(y_part);
  if (!(permanent >= bounds::kOrientMin && permanent <= bounds::kFiniteMax)) {
    const Point points[3] = {a, b, p};
    if (!exact_integer::coordinates_within(points, 3, -400, 500)) return exact_integer::dot_sign(a, b, p);
  }
  // Rounding never flips the sign of a difference or a product (barring underflow), so terms of
  // equal sign decide alone; otherwise the orient2d filter bound applies to this sum unchanged.
  if ((x_part <= 0.0) == (y_part <= 0.0) || x_part == 0.0 || y_part == 0.0) return (dot > 0.0) - (dot < 0.0);
  const double bound = bounds::kOrientA * permanent;
  if (dot > bound) return 1;
  if (-dot > bound) return -1;
  double exact_dot[exact::kDotMax];
  const int n = exact::diametral_dot(a, b, p, exact_dot);
  return expansion::sign(exact_dot, n);
}

EncroachRule EncroachRule::circle() { return EncroachRule{90.0, 0.0}; }

EncroachRule EncroachRule::lens(double theta_deg) {
  const double apex = theta_deg >= 45.0 ? 90.0 : 180.0 - 2.0 * theta_deg;
  const double c = std::cos(apex * std::numbers::pi / 180.0);
  return EncroachRule{apex, c * c};
}

bool encroaches(Predicates& pred, const Point& a, const Point& b, const Point& p, const EncroachRule& rule) {
  const int sign = diametral_dot_sign(a, b, p);
  if (rule.min_apex_angle_deg <= 90.0) return sign <= 0;
  if (sign > 0) return false;  // an acute angle at p: outside every lens
  // On the open subsegment the apex angle is 180 degrees, which every rule accepts.
  if (pred.orient2d(a, b, p) == 0.0) return sign < 0;
  if (rule.min_apex_angle_deg >= 180.0) return false;
  // angle >= apex  <=>  cos(angle) <= cos(apex) < 0  <=>  dot^2 >= cos^2(apex) |pa|^2 |pb|^2.
  const double ax = a.x - p.x, ay = a.y - p.y, bx = b.x - p.x, by = b.y - p.y;
  const double dot = ax * bx + ay * by;
  return dot * dot >= rule.cos2_apex * (ax * ax + ay * ay) * (bx * bx + by * by);
}

}  // namespace deltri
