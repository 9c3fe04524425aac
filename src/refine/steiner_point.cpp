#include "refine/steiner_point.h"

#include <cmath>
#include <numbers>

namespace deltri {

Point circumcenter_of(const Point& a, const Point& b, const Point& c) {
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double denominator = 2.0 * (bx * cy - by * cx);
  return Point{a.x + (cy * b2 - by * c2) / denominator, a.y + (bx * c2 - cx * b2) / denominator};
}

double off_center_constant(double min_angle_deg, bool off_centers) {
  if (!off_centers || min_angle_deg <= 0.0) return 0.0;
  const double half = 0.5 * min_angle_deg * std::numbers::pi / 180.0;
  return 0.475 / std::tan(half);
}

Point steiner_point(const Mesh& mesh, EdgeRef shortest, double off_constant) {
  const Point& p = mesh.point(mesh.org(shortest));
  const Point& q = mesh.point(mesh.dest(shortest));
  const Point& r = mesh.point(mesh.apex(shortest));
  const Point centre = circumcenter_of(p, q, r);
  if (off_constant <= 0.0) return centre;
  const Point mid{0.5 * (p.x + q.x), 0.5 * (p.y + q.y)};
  const double dx = centre.x - mid.x, dy = centre.y - mid.y;
  const double to_centre = std::sqrt(dx * dx + dy * dy);
  const double height = off_constant * std::sqrt((q.x - p.x) * (q.x - p.x) + (q.y - p.y) * (q.y - p.y));
  if (!(height < to_centre)) return centre;
  const double s = height / to_centre;
  return Point{mid.x + s * dx, mid.y + s * dy};
}

}  // namespace deltri
