#include "refine/termination_guard.h"

#include <algorithm>
#include <cmath>

namespace deltri {
namespace {

double distance(const Point& a, const Point& b) { return std::hypot(b.x - a.x, b.y - a.y); }

// Distance from the apex of e to the line of e: twice the area over the base.
double apex_height(const Mesh& mesh, EdgeRef e) {
  const Point& a = mesh.point(mesh.org(e));
  const Point& b = mesh.point(mesh.dest(e));
  const Point& c = mesh.point(mesh.apex(e));
  const double twice_area = std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
  return twice_area / distance(a, b);
}

}  // namespace

std::vector<double> initial_feature_sizes(const Mesh& mesh) {
  std::vector<double> f(mesh.vertex_count(), HUGE_VAL);
  for (EdgeRef e = 0; e < mesh.corner.size(); ++e) {
    if (mesh.corner[e] == kNone) continue;
    const VertexId a = mesh.org(e), b = mesh.dest(e);
    const double length = distance(mesh.point(a), mesh.point(b));
    f[a] = std::min(f[a], length);
    f[b] = std::min(f[b], length);
    if (mesh.has_subsegments() && mesh.subseg[e] != kNone) {
      const VertexId c = mesh.apex(e);
      f[c] = std::min(f[c], apex_height(mesh, e));
    }
  }
  return f;
}

double precision_floor(const Mesh& mesh) {
  double largest = 0.0;
  for (const Point& p : mesh.points)
    if (std::isfinite(p.x) && std::isfinite(p.y))
      largest = std::max({largest, std::fabs(p.x), std::fabs(p.y)});
  return std::ldexp(largest, -kPrecisionOctaves);
}

double guard_floor(double feature, double size_floor) {
  const double scale = size_floor > 0.0 ? std::min(feature, size_floor) : feature;
  return std::ldexp(scale, -kGuardOctaves);
}

}  // namespace deltri
