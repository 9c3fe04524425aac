#include "refine/area_field.h"

#include <algorithm>
#include <cmath>

namespace deltri {
namespace {

bool bounds_vary(const Mesh& mesh) {
  if (mesh.area_bound.empty()) return false;
  for (EdgeRef e = 0; e < mesh.corner.size(); ++e) {
    if (mesh.corner[e] == kNone || mesh.link[e] == kNone) continue;
    if (mesh.has_subsegments() && mesh.subseg[e] != kNone) continue;
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
  double hi_x = -HUGE_VAL, hi_y = -HUGE_VAL;
  field.lo_x_ = field.lo_y_ = HUGE_VAL;
  for (TriangleId t = 0; t < mesh.triangle_slots(); ++t) {
    if (!mesh.is_live(t)) continue;
    const Triangle tri{mesh.point(mesh.corner[3 * t]), mesh.point(mesh.corner[3 * t + 1]),
                       mesh.point(mesh.corner[3 * t + 2]), mesh.area_bound[t]};
    for (const Point& p : {tri.a, tri.b, tri.c}) {
      field.lo_x_ = std::min(field.lo_x_, p.x), field.lo_y_ = std::min(field.lo_y_, p.y);
      hi_x = std::max(hi_x, p.x), hi_y = std::max(hi_y, p.y);
    }
    field.triangles_.push_back(tri);
  }
  // About two triangles a cell.
  const double width = std::max(hi_x - field.lo_x_, hi_y - field.lo_y_);
  const double cells = std::max(1.0, field.triangles_.size() / 2.0);
  field.cell_size_ = width > 0.0 ? width / std::ceil(std::sqrt(cells)) : 1.0;
  field.columns_ = static_cast<std::size_t>((hi_x - field.lo_x_) / field.cell_size_) + 1;
  field.rows_ = static_cast<std::size_t>((hi_y - field.lo_y_) / field.cell_size_) + 1;
  // Two passes over the triangles' boxes: count per cell, then fill.
  std::vector<std::uint32_t> count(field.columns_ * field.rows_ + 1, 0);
  const auto each_cell = [&](const Triangle& t, auto&& visit) {
    const std::size_t c0 = field.cell_of(std::min({t.a.x, t.b.x, t.c.x}), std::min({t.a.y, t.b.y, t.c.y}));
    const std::size_t c1 = field.cell_of(std::max({t.a.x, t.b.x, t.c.x}), std::max({t.a.y, t.b.y, t.c.y}));
    for (std::size_t row = c0 / field.columns_; row <= c1 / field.columns_; ++row)
      for (std::size_t col = c0 % field.columns_; col <= c1 % field.columns_; ++col) visit(row * field.columns_ + col);
  };
  for (const Triangle& t : field.triangles_) each_cell(t, [&](std::size_t c) { ++count[c + 1]; });
  for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  field.cell_start_ = count;
  field.cell_list_.resize(count.back());
  for (std::uint32_t i = 0; i < field.triangles_.size(); ++i)
    each_cell(field.triangles_[i], [&](std::size_t c) { field.cell_list_[count[c]++] = i; });
  return field;
}

std::size_t AreaField::cell_of(double x, double y) const {
  const auto clamp = [](double v, std::size_t n) {
    return static_cast<std::size_t>(std::clamp(v, 0.0, static_cast<double>(n - 1)));
  };
  return clamp((y - lo_y_) / cell_size_, rows_) * columns_ + clamp((x - lo_x_) / cell_size_, columns_);
}

double AreaField::bound_at(const Point& p) const {
  const std::size_t c = cell_of(p.x, p.y);
  double inside = 0.0, anywhere = 0.0;
  bool found = false;
  for (std::uint32_t k = cell_start_[c]; k < cell_start_[c + 1]; ++k) {
    const Triangle& t = triangles_[cell_list_[k]];
    anywhere = tighter(anywhere, t.bound);
    if (left_of_or_on(t.a, t.b, p) && left_of_or_on(t.b, t.c, p) && left_of_or_on(t.c, t.a, p)) {
      inside = found ? tighter(inside, t.bound) : t.bound;
      found = true;
    }
  }
  return found ? inside : anywhere;
}

}  // namespace deltri
