#include "refine/bad_triangles.h"

#include <algorithm>
#include <cmath>

#include "geometry/constructions.h"
#include "geometry/lattice.h"

namespace deltri {
namespace {

bool has_subsegment(const Mesh& mesh, EdgeRef e) {
  return mesh.has_subsegments() && mesh.subseg.has(e);
}

}  // namespace

double area_bound_of(const Mesh& mesh, TriangleId t, const QualityRules& rules) {
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
  TriangleShape shape;
  const VertexId* corners = mesh.corners_at(t);
  const Point& a = mesh.point(corners[0]);
  const Point& b = mesh.point(corners[1]);
  const Point& c = mesh.point(corners[2]);
  double* len2 = shape.length2;
  len2[0] = squared_distance(a, b);
  len2[1] = squared_distance(b, c);
  len2[2] = squared_distance(c, a);
  const unsigned s = shortest_side(len2);
  shape.shortest = edge_of(t, s);
  shape.shortest_length2 = len2[s];
  const double twice_area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  shape.area = 0.5 * twice_area;
  const double others = len2[(s + 1) % 3] * len2[(s + 2) % 3];
  shape.ratio2_over_bound2 = twice_area > 0.0 ? others * sin2_theta / (twice_area * twice_area)
                                              : HUGE_VAL;
  return shape;
}

Assessment assess_triangle(const Mesh& mesh, TriangleId t, const QualityRules& rules) {
  Assessment out;
  out.shape = measure_triangle(mesh, t, rules.angle.sin2());
  const double* len2 = out.shape.length2;
  if (rules.angle.sin2() > 0.0 && out.shape.ratio2_over_bound2 > 1.0) {
    // With ties for the shortest edge, any tied smallest angle between subsegments exempts t.
    bool exempt = false;
    for (unsigned i = 0; i < 3 && !exempt; ++i)
      exempt = len2[i] == out.shape.shortest_length2 && angle_between_subsegments(mesh, edge_of(t, i));
    out.skinny = !exempt;
  }
  const double area = out.shape.area;
  if (rules.size.max_area > 0.0 && area > rules.size.max_area) out.too_large = true;
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

double size_excess(const Mesh& mesh, TriangleId t, const TriangleShape& shape, const QualityRules& rules) {
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

}  // namespace deltri
