#include "refine/criteria.h"

#include <algorithm>
#include <cmath>

#include <numbers>

#include "geometry/constructions.h"
#include "geometry/encroachment.h"
#include "geometry/exact_determinants.h"
#include "geometry/expansion.h"
#include "geometry/lattice.h"

namespace deltri {
namespace {

bool has_subsegment(const Mesh& mesh, EdgeRef e) {
  return mesh.has_subsegments() && mesh.subseg.has(e);
}

// The sign of dot^2 - cos2 |u|^2 |v|^2 for u = a - p, v = b - p, in expansion arithmetic: each
// factor exact (exact::diametral_dot), their products exact.
int obtuse_excess_sign(const Point& p, const Point& a, const Point& b, double cos2) {
  double dot[exact::kDotMax], uu[exact::kDotMax], vv[exact::kDotMax];
  const int nd = exact::diametral_dot(a, b, p, dot);
  const int nu = exact::diametral_dot(a, a, p, uu);
  const int nv = exact::diametral_dot(b, b, p, vv);
  std::vector<double> d2(2 * nd * nd + 1), n2(2 * nu * nv + 1), s2(2 * n2.size() + 1), diff(d2.size() + s2.size());
  std::vector<double> scratch(2 * std::max(nd * (nd + 1), nu * (nv + 1)) + 2);
  const int l1 = expansion::multiply(dot, nd, dot, nd, d2.data(), scratch.data());
  const int l2 = expansion::multiply(uu, nu, vv, nv, n2.data(), scratch.data());
  const int l3 = expansion::scale(n2.data(), l2, -cos2, s2.data());
  const int l4 = expansion::sum(d2.data(), l1, s2.data(), l3, diff.data());
  return expansion::sign(diff.data(), l4);
}

}  // namespace

double area_bound_of(const Mesh& mesh, TriangleId t, const Criteria& rules) {
  if (!rules.size.triangle_bounds || mesh.area_bound.empty()) return 0.0;
  if (rules.area_field == nullptr || rules.area_field->empty()) return mesh.area_bound[t];
  const auto [a, b, c] = mesh.corner_points(t);
  return rules.area_field->bound_at({(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0});
}

bool is_current(const Mesh& mesh, const QueuedTriangle& entry) {
  const TriangleId t = entry.triangle;
  if (t >= mesh.triangle_slots() || !mesh.is_live(t)) return false;
  const VertexId* c = mesh.corners_at(t);
  for (VertexId v : {entry.a, entry.b, entry.c})
    if (c[0] != v && c[1] != v && c[2] != v) return false;
  return true;
}

bool angle_between_subsegments(const Mesh& mesh, EdgeRef e) {
  return has_subsegment(mesh, lnext(e)) && has_subsegment(mesh, lprev(e));
}

// Each corner and point is read once: this runs for every triangle around every new vertex.
TriangleShape measure_triangle(const Mesh& mesh, TriangleId t, double sin2_theta) {
  return measure_triangle(t, side_measures(mesh, t), sin2_theta);
}

TriangleShape measure_triangle(TriangleId t, const SideMeasures& m, double sin2_theta) {
  TriangleShape shape;
  std::copy(m.length2, m.length2 + 3, shape.length2);
  const unsigned s = shortest_side(m.length2);
  shape.shortest = edge_of(t, s);
  shape.shortest_length2 = m.length2[s];
  const double twice_area = m.twice_area;
  shape.area = 0.5 * twice_area;
  shape.ratio2_over_bound2 = ratio2_over_bound2(m, s, sin2_theta);
  return shape;
}

Assessment assess_triangle(const Mesh& mesh, TriangleId t, const Criteria& rules) {
  return assess_triangle(mesh, t, rules, side_measures(mesh, t));
}

Assessment assess_triangle(const Mesh& mesh, TriangleId t, const Criteria& rules, const SideMeasures& m) {
  Assessment out;
  out.shape = measure_triangle(t, m, rules.angle.sin2());
  const double* len2 = out.shape.length2;
  if (above_ratio_bound(out.shape.ratio2_over_bound2, rules.angle)) {
    // With ties for the shortest edge, any tied smallest angle between subsegments exempts t.
    bool exempt = false;
    for (unsigned i = 0; i < 3 && !exempt; ++i)
      exempt = len2[i] == out.shape.shortest_length2 && angle_between_subsegments(mesh, edge_of(t, i));
    out.skinny = !exempt;
  }
  if (rules.max_angle.asked()) {
    const auto [a, b, c] = mesh.corner_points(t);
    const int k = corner_above(a, b, c, rules.max_angle);  // the corner opposite side k + 1
    out.too_obtuse = k >= 0 && !angle_between_subsegments(mesh, edge_of(t, (static_cast<unsigned>(k) + 1) % 3));
  }
  const double area = out.shape.area;
  if (above_max_area(area, rules.size)) out.too_large = true;
  if (const double bound = area_bound_of(mesh, t, rules); bound > 0.0 && area > bound) out.too_large = true;
  if (rules.size.max_edge_length > 0.0) {
    const double limit2 = rules.size.max_edge_length * rules.size.max_edge_length;
    for (unsigned i = 0; i < 3; ++i)
      if (len2[i] > limit2) out.too_large = true;
  }
  if (rules.size_test && !out.too_large) {
    const VertexId* c = mesh.corners_at(t);
    out.too_large = (*rules.size_test)(mesh.point(c[0]), mesh.point(c[1]), mesh.point(c[2]), area);
  }
  return out;
}

double size_excess(const Mesh& mesh, TriangleId t, const TriangleShape& shape, const Criteria& rules) {
  double excess = 0.0;
  if (rules.size.max_area > 0.0) excess = std::max(excess, shape.area / rules.size.max_area);
  if (const double bound = area_bound_of(mesh, t, rules); bound > 0.0) excess = std::max(excess, shape.area / bound);
  if (rules.size.max_edge_length > 0.0) {
    const double longest2 = std::max({shape.length2[0], shape.length2[1], shape.length2[2]});
    excess = std::max(excess, longest2 / (rules.size.max_edge_length * rules.size.max_edge_length));
  }
  return excess;
}

double triangle_sine2(const Mesh& mesh, TriangleId t) {
  const auto [a, b, c] = mesh.corner_points(t);
  return smallest_angle_sine2(a, b, c);
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
      if (meets_angle(smallest_angle_sine2(p, q, Point{x, y}), sin2_theta)) return false;
  return true;
}

double angle_degrees(const Point& a, const Point& b, const Point& c) {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * (180.0 / std::numbers::pi);
}

// The filter: -dot / (|u| |v|) is the angle's -cos, known in doubles to a few ulps (each coordinate
// difference and product rounds once), so a gap of 1e-9 from -cos A leaves only near ties to the
// exact test. For A = 90 the encroachment test's own filter and exact fallback decide dot < 0.
bool angle_exceeds(const Point& p, const Point& a, const Point& b, const LargestAngleBound& bound) {
  if (!bound.asked()) return false;
  if (bound.cosine() == 0.0) return diametral_dot_sign(a, b, p) < 0;
  const double ux = a.x - p.x, uy = a.y - p.y, vx = b.x - p.x, vy = b.y - p.y;
  const double dot = ux * vx + uy * vy;
  const double norms = std::sqrt(ux * ux + uy * uy) * std::sqrt(vx * vx + vy * vy);
  const double minus_cos = -dot / norms, limit = -bound.cosine();
  if (std::isfinite(minus_cos) && norms > 1e-150 && norms < 1e150) {
    if (minus_cos > limit + 1e-9) return true;
    if (minus_cos < limit - 1e-9) return false;
  }
  return diametral_dot_sign(a, b, p) < 0 && obtuse_excess_sign(p, a, b, bound.cos2()) > 0;
}

int corner_above(const Point& a, const Point& b, const Point& c, const LargestAngleBound& bound) {
  if (!bound.asked()) return -1;
  if (angle_exceeds(a, b, c, bound)) return 0;
  if (angle_exceeds(b, c, a, bound)) return 1;
  if (angle_exceeds(c, a, b, bound)) return 2;
  return -1;
}

double angle_margin(const Point& a, const Point& b, const Point& c, const AngleBound& angle,
                    const LargestAngleBound& max_angle) {
  const double sine2 = smallest_angle_sine2(a, b, c);
  if (!(sine2 > 0.0)) return -2.0;  // clockwise or flat
  double margin = angle.sin2() > 0.0 ? sine2 - angle.sin2() : 1.0;
  if (!max_angle.asked()) return margin;
  const Point* at[3] = {&a, &b, &c};
  for (unsigned k = 0; k < 3; ++k) {
    const Point& p = *at[k];
    const Point& u = *at[(k + 1) % 3];
    const Point& v = *at[(k + 2) % 3];
    const double ux = u.x - p.x, uy = u.y - p.y, vx = v.x - p.x, vy = v.y - p.y;
    const double cosine = (ux * vx + uy * vy) / std::sqrt((ux * ux + uy * uy) * (vx * vx + vy * vy));
    margin = std::min(margin, cosine - max_angle.cosine());
  }
  return margin;
}

namespace {

constexpr double kMargin = 1e-12;  // BoundCheck's
constexpr double kTiny = 1e-250;

}  // namespace

BoundCheck::BoundCheck(const AngleBound& angle, const SizeBounds& size, const LargestAngleBound& max_angle)
    : limit_(angle.degrees() * (1.0 - kMargin)),
      tangent_(std::tan(limit_ * (std::numbers::pi / 180.0))),
      clear_sine2_(std::pow(std::sin(limit_ * (std::numbers::pi / 180.0)), 2) * (1.0 + 1e-6)),
      size_(size),
      max_angle_(max_angle) {}

// The angle test without atan2 where the answer is clear: the corner's angle is atan2(cross, dot),
// so with dot > 0 it is below `limit` degrees exactly when cross < tan(limit) dot. A relative gap
// of 1e-9, far beyond the rounding of either form, leaves only the near ties to atan2, so every
// answer is the one atan2 gives (most triangles of a refined mesh are clear of the bound).
int BoundCheck::clear_side(const Point& a, const Point& b, const Point& c) const {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = c.x - a.x, vy = c.y - a.y;
  const double cross = std::fabs(ux * vy - uy * vx), dot = ux * vx + uy * vy;
  if (limit_ >= 89.0) return 0;
  if (!(dot > kTiny)) return dot < -kTiny ? 1 : 0;  // obtuse; or tiny, where products lose bits
  if (cross > tangent_ * dot * (1.0 + 1e-9)) return 1;
  if (cross < tangent_ * dot * (1.0 - 1e-9)) return -1;
  return 0;
}

bool BoundCheck::below(const Point& a, const Point& b, const Point& c) const {
  const int side = clear_side(a, b, c);
  return side != 0 ? side < 0 : angle_degrees(a, b, c) < limit_;
}

// Most triangles of a refined mesh clear the limit at every corner by far, which one measure of
// the smallest angle says (smallest_angle_sine2, good to a few ulps where its products neither
// underflow nor overflow) where three corner tests would say the same: a relative 1e-6 above the
// limit's sin^2 is far beyond the rounding of either. Anything else goes to the corner tests.
bool BoundCheck::clears_every_corner(const Point& a, const Point& b, const Point& c) const {
  const double abx = b.x - a.x, aby = b.y - a.y, acx = c.x - a.x, acy = c.y - a.y;
  const double bcx = c.x - b.x, bcy = c.y - b.y;
  const double ab = abx * abx + aby * aby, bc = bcx * bcx + bcy * bcy, ca = acx * acx + acy * acy;
  const double largest = std::max({ab * bc, bc * ca, ca * ab});
  if (!(largest > 1e-250 && largest < 1e250)) return false;
  return smallest_angle_sine2(a, b, c) > clear_sine2_;
}

bool BoundCheck::misses_angle(const Point& a, const Point& b, const Point& c) const {
  if (limit_ <= 0.0 || clears_every_corner(a, b, c)) return false;
  return below(a, b, c) || below(b, c, a) || below(c, a, b);
}

bool BoundCheck::misses_size(const Mesh& m, TriangleId t, const Point& a, const Point& b, const Point& c) const {
  const double area = 0.5 * std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  if (size_.max_area > 0.0 && area > size_.max_area * (1.0 + kMargin)) return true;
  if (size_.triangle_bounds && m.area_bound.size() == m.triangle_slots() && m.area_bound[t] > 0.0 &&
      area > m.area_bound[t] * (1.0 + kMargin))
    return true;
  if (size_.max_edge_length <= 0.0) return false;
  const auto length = [](const Point& p, const Point& q) { return std::hypot(q.x - p.x, q.y - p.y); };
  const double longest = std::max({length(a, b), length(b, c), length(c, a)});
  return longest > size_.max_edge_length * (1.0 + kMargin);
}

}  // namespace deltri
