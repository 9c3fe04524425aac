#include "refine/termination_guard.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "geometry/constructions.h"

namespace deltri {
namespace {

double distance(const Point& a, const Point& b) { return std::hypot(b.x - a.x, b.y - a.y); }

double twice_area_of(const Point& a, const Point& b, const Point& c) {
  return std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

}  // namespace

// An edge's length counts once, from the side with the smaller id (the twin's length is the same
// number: hypot ignores the signs); a subsegment's apex height counts from both sides.
std::vector<double> initial_feature_sizes(const Mesh& mesh) {
  std::vector<double> f(mesh.vertex_count(), HUGE_VAL);
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
    if (mesh.corner[e] == kNone) continue;
    const bool first = mesh.link[e] == kNone || e < mesh.link[e];
    const bool constrained = mesh.has_subsegments() && mesh.subseg.has(e);
    if (!first && !constrained) continue;
    const VertexId a = mesh.org(e), b = mesh.dest(e);
    const double length = distance(mesh.point(a), mesh.point(b));
    if (first) {
      f[a] = std::min(f[a], length);
      f[b] = std::min(f[b], length);
    }
    if (constrained) {  // the apex's distance to the subsegment's line: twice the area over the base
      const VertexId c = mesh.apex(e);
      f[c] = std::min(f[c], twice_area_of(mesh.point(a), mesh.point(b), mesh.point(c)) / length);
    }
  }
  return f;
}

double smallest_input_angle(const Mesh& mesh) {
  double smallest = HUGE_VAL;
  if (!mesh.has_subsegments()) return smallest;
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
    if (mesh.corner[e] == kNone || !mesh.subseg.has(e)) continue;
    const Point& v = mesh.point(mesh.org(e));
    const Point& to = mesh.point(mesh.dest(e));
    // Turn counter-clockwise around v, through the triangles, to the next subsegment.
    for (EdgeRef g = e;;) {
      const EdgeRef in = lprev(g);  // apex(g) -> v
      if (mesh.subseg.has(in)) {
        if (mesh.org(in) == mesh.dest(e)) break;  // e itself from its other side: v is a free end
        const Point& x = mesh.point(mesh.org(in));
        const double ux = to.x - v.x, uy = to.y - v.y, wx = x.x - v.x, wy = x.y - v.y;
        double angle = std::atan2(ux * wy - uy * wx, ux * wx + uy * wy);
        if (angle < 0.0) angle += 2.0 * std::numbers::pi;
        smallest = std::min(smallest, angle);
        break;
      }
      g = mesh.link[in];
      if (g == kNone || g == e) break;
    }
  }
  return smallest;
}

double angle_scale(double angle) {
  if (!(angle < std::numbers::pi / 3.0)) return 1.0;
  return std::max(2.0 * std::sin(0.5 * angle), 0.0);
}

double proven_angle_deg(SplitRule rule) {
  const double ratio = rule == SplitRule::DiametralCircles ? std::sqrt(2.0)
                       : rule == SplitRule::DiametralLenses ? 2.0 / std::sqrt(3.0)
                                                            : std::sqrt(5.0) / 2.0;  // B
  return std::asin(1.0 / (2.0 * ratio)) * 180.0 / std::numbers::pi;
}

bool within_proven_range(double smallest_input_angle, double angle_bound_deg, SplitRule rule) {
  const double sixty = std::numbers::pi / 3.0 * (1.0 - kSixtySlack);
  return smallest_input_angle >= sixty && angle_bound_deg <= proven_angle_deg(rule);
}

double precision_floor_at(const Point& p) {
  return std::ldexp(magnitude(p), -kPrecisionOctaves);
}

double guard_floor(double feature, double size_floor) {
  const double scale = size_floor > 0.0 ? std::min(feature, size_floor) : feature;
  return std::ldexp(scale, -kGuardOctaves);
}

double triangles_wanted(const Mesh& mesh, const SizeBounds& bounds) {
  double wanted = 0.0;
  const double edge_area = bounds.max_edge_length > 0.0
                               ? std::sqrt(3.0) / 4.0 * bounds.max_edge_length * bounds.max_edge_length
                               : HUGE_VAL;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    const auto [a, b, c] = mesh.corner_points(t);
    const double area = 0.5 * twice_area_of(a, b, c);
    double bound = std::min(bounds.max_area > 0.0 ? bounds.max_area : HUGE_VAL, edge_area);
    if (bounds.triangle_bounds && t < mesh.area_bound.size() && mesh.area_bound[t] > 0.0)
      bound = std::min(bound, mesh.area_bound[t]);
    if (bound < HUGE_VAL) wanted += area / bound;
  }
  return wanted;
}

namespace {

std::uint64_t to_count(double x) { return x < 1.8e19 ? static_cast<std::uint64_t>(x) : UINT64_MAX; }

}  // namespace

double feature_work(const Mesh& mesh) { return feature_work(mesh, initial_feature_sizes(mesh)); }

double feature_work(const Mesh& mesh, const std::vector<double>& f) {
  std::vector<double> longest(mesh.vertex_count(), 0.0);
  double work = 0.0;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    const std::array<VertexId, 3> v = mesh.corners(t);
    const Point* p[3] = {&mesh.point(v[0]), &mesh.point(v[1]), &mesh.point(v[2])};
    const double twice_area = twice_area_of(*p[0], *p[1], *p[2]);
    const double smallest_f = std::min({f[v[0]], f[v[1]], f[v[2]]});
    double longest_edge = 0.0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const double edge = distance(*p[i], *p[j]);
      longest_edge = std::max(longest_edge, edge);
      longest[v[i]] = std::max(longest[v[i]], edge);
      longest[v[j]] = std::max(longest[v[j]], edge);
      const double across = std::max(edge > 0.0 ? twice_area / edge : 0.0, std::min(f[v[i]], f[v[j]]));
      if (across > 0.0 && std::isfinite(across)) work += 0.5 * edge / across;
    }
    const double s = std::max(longest_edge > 0.0 ? twice_area / longest_edge : 0.0, smallest_f);
    if (s > 0.0 && std::isfinite(s)) work += 0.5 * twice_area / (s * s);
  }
  for (VertexId u{0}; u < mesh.vertex_count(); ++u)
    if (f[u] > 0.0 && std::isfinite(f[u])) work += std::log2(1.0 + longest[u] / f[u]);
  return work;
}

std::uint64_t steiner_cap(const Mesh& mesh, const SizeBounds& bounds) {
  return steiner_cap(mesh, bounds, initial_feature_sizes(mesh));
}

std::uint64_t steiner_cap(const Mesh& mesh, const SizeBounds& bounds, const std::vector<double>& features) {
  const double cap = kCapPerWork * feature_work(mesh, features) +
                     static_cast<double>(kCapPerVertex) * mesh.vertex_count() + 4.0 * triangles_wanted(mesh, bounds);
  return to_count(cap);
}

std::uint64_t memory_cap(std::uint64_t triangle_slots, double memory_budget) {
  if (!(memory_budget > 0.0)) return UINT64_MAX;
  const double used = kBytesPerTriangle * static_cast<double>(triangle_slots);
  return memory_budget > used ? to_count((memory_budget - used) / kBytesPerSteiner) : 0;
}

}  // namespace deltri
