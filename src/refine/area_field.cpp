#include "refine/area_field.h"

#include <algorithm>
#include <cmath>

namespace deltri {
namespace {

bool bounds_vary(const Mesh& mesh) {
  if (mesh.area_bound.empty()) return false;
  for (EdgeRef e{0}; e < mesh.corner.size(); ++e) {
    if (mesh.corner[e] == kNone || mesh.link[e] == kNone) continue;
    if (mesh.has_subsegments() && mesh.subseg.has(e)) continue;
    if (mesh.area_bound[triangle_of(e)] != mesh.area_bound[triangle_of(mesh.link[e])]) return true;
  }
  return false;
}

// The tighter of two bounds (<= 0: none).
double tighter(double a, double b) {
  if (!(a > 0.0)) return b;
  if (!(b > 0.0)) return a;
  return std::min(a, b);
}

// Twice the signed area of (a, b, p), with the rounding slack of that product.
bool left_of_or_on(const Point& a, const Point& b, const Point& p) {
  const double l = (b.x - a.x) * (p.y - a.y);
  const double r = (b.y - a.y) * (p.x - a.x);
  return l - r >= -1e-12 * (std::fabs(l) + std::fabs(r));
}

}  // namespace

AreaField AreaField::of(const Mesh& mesh) {
  AreaField field;
  if (!bounds_vary(mesh)) return field;
  std::vector<Box> boxes;
  Box all;
  for (TriangleId t{0}; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    const auto [a, b, c] = mesh.corner_points(t);
    const Triangle tri{a, b, c, mesh.area_bound[t]};
    Box box;
    for (const Point& p : {tri.a, tri.b, tri.c}) box.add(p), all.add(p);
    boxes.push_back(box);
    field.triangles_.push_back(tri);
  }
  // About two triangles a cell.
  const double width = std::max(all.width(), all.height());
  const double cells = std::max(1.0, field.triangles_.size() / 2.0);
  field.grid_ = TriangleGrid(boxes, all, width > 0.0 ? width / std::ceil(std::sqrt(cells)) : 1.0);
  return field;
}

double AreaField::bound_at(const Point& p) const {
  double inside = 0.0, anywhere = 0.0;
  bool found = false;
  for (std::uint32_t k : grid_.near(p)) {
    const Triangle& t = triangles_[k];
    anywhere = tighter(anywhere, t.bound);
    if (left_of_or_on(t.a, t.b, p) && left_of_or_on(t.b, t.c, p) && left_of_or_on(t.c, t.a, p)) {
      inside = found ? tighter(inside, t.bound) : t.bound;
      found = true;
    }
  }
  return found ? inside : anywhere;
}

}  // namespace deltri
