#include "refine/encroached.h"

#include <cmath>
#include <numbers>

#include "refine/exact_dot.h"

namespace deltri {

EncroachRule diametral_circle_rule() { return EncroachRule{90.0}; }

EncroachRule diametral_lens_rule(double theta_deg) {
  return EncroachRule{theta_deg >= 45.0 ? 90.0 : 180.0 - 2.0 * theta_deg};
}

bool encroaches(Predicates& pred, const Point& x, const Point& y, const Point& w,
                const EncroachRule& rule) {
  const int sign = dot_sign(x, y, w);
  if (rule.min_apex_angle_deg <= 90.0) return sign <= 0;
  if (sign > 0) return false;
  // On the open subsegment the apex angle is 180 degrees, which every rule accepts.
  if (pred.orient2d(x, y, w) == 0.0) return sign < 0;
  if (rule.min_apex_angle_deg >= 180.0) return false;
  // angle >= phi  <=>  cos(angle) <= cos(phi) < 0  <=>  dot^2 >= cos^2(phi) |xw|^2 |yw|^2.
  const double ax = x.x - w.x, ay = x.y - w.y, bx = y.x - w.x, by = y.y - w.y;
  const double dot = ax * bx + ay * by;
  const double c = std::cos(rule.min_apex_angle_deg * std::numbers::pi / 180.0);
  return dot * dot >= c * c * (ax * ax + ay * ay) * (bx * bx + by * by);
}

bool is_encroached(const Mesh& mesh, Predicates& pred, EdgeRef e, const EncroachRule& rule) {
  const Point& x = mesh.point(mesh.org(e));
  const Point& y = mesh.point(mesh.dest(e));
  if (encroaches(pred, x, y, mesh.point(mesh.apex(e)), rule)) return true;
  const EdgeRef twin = mesh.sym(e);
  return twin != kNone && encroaches(pred, x, y, mesh.point(mesh.apex(twin)), rule);
}

}  // namespace deltri
