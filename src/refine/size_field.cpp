#include "refine/size_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace deltri {
namespace {

double cross(const Point& a, const Point& b, const Point& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Barycentric weights may fall this far below zero for a point on a shared side (rounding).
constexpr double kTolerance = 1e-12;

// The area of the equilateral triangle of edge 1.
const double kEquilateralArea = std::sqrt(3.0) / 4.0;

}  // namespace

SizeField::SizeField(std::vector<Point> points, std::vector<double> lengths, const std::vector<std::uint32_t>& corners)
    : points_(std::move(points)), lengths_(std::move(lengths)) {
  for (std::size_t k = 0; k + 2 < corners.size(); k += 3) {
    const Triangle t{{corners[k], corners[k + 1], corners[k + 2]}};
    if (cross(points_[t.v[0]], points_[t.v[1]], points_[t.v[2]]) != 0.0) triangles_.push_back(t);
  }
  if (triangles_.empty()) return;
  // A grid of about one triangle per cell over the background triangles' box.
  double hi_x = -HUGE_VAL, hi_y = -HUGE_VAL;
  lo_x_ = lo_y_ = HUGE_VAL;
  for (const Triangle& t : triangles_)
    for (std::uint32_t v : t.v) {
      lo_x_ = std::min(lo_x_, points_[v].x), lo_y_ = std::min(lo_y_, points_[v].y);
      hi_x = std::max(hi_x, points_[v].x), hi_y = std::max(hi_y, points_[v].y);
    }
  const double width = std::max(hi_x - lo_x_, 1e-300), height = std::max(hi_y - lo_y_, 1e-300);
  cell_size_ = std::max(std::sqrt(width * height / static_cast<double>(triangles_.size())), std::max(width, height) / 4096.0);
  columns_ = static_cast<std::size_t>(width / cell_size_) + 1;
  rows_ = static_cast<std::size_t>(height / cell_size_) + 1;
  // Two passes over the triangles' boxes: count per cell, then fill.
  std::vector<std::uint32_t> count(columns_ * rows_ + 1, 0);
  const auto each_cell = [&](const Triangle& t, auto&& visit) {
    double x0 = HUGE_VAL, y0 = HUGE_VAL, x1 = -HUGE_VAL, y1 = -HUGE_VAL;
    for (std::uint32_t v : t.v) {
      x0 = std::min(x0, points_[v].x), y0 = std::min(y0, points_[v].y);
      x1 = std::max(x1, points_[v].x), y1 = std::max(y1, points_[v].y);
    }
    const std::size_t c0 = cell_of(x0, y0), c1 = cell_of(x1, y1);
    for (std::size_t r = c0 / columns_; r <= c1 / columns_; ++r)
      for (std::size_t c = c0 % columns_; c <= c1 % columns_; ++c) visit(r * columns_ + c);
  };
  for (const Triangle& t : triangles_) each_cell(t, [&](std::size_t cell) { ++count[cell + 1]; });
  for (std::size_t i = 1; i < count.size(); ++i) count[i] += count[i - 1];
  cell_start_ = count;
  cell_list_.resize(count.back());
  for (std::uint32_t k = 0; k < triangles_.size(); ++k) each_cell(triangles_[k], [&](std::size_t cell) { cell_list_[count[cell]++] = k; });
}

std::size_t SizeField::cell_of(double x, double y) const {
  const auto clamp = [](double v, std::size_t n) {
    return v <= 0.0 ? std::size_t{0} : std::min(static_cast<std::size_t>(v), n - 1);
  };
  return clamp((y - lo_y_) / cell_size_, rows_) * columns_ + clamp((x - lo_x_) / cell_size_, columns_);
}

bool SizeField::interpolate(const Triangle& t, const Point& p, double& h) const {
  const Point &a = points_[t.v[0]], &b = points_[t.v[1]], &c = points_[t.v[2]];
  const double whole = cross(a, b, c);
  const double wa = cross(p, b, c) / whole, wb = cross(a, p, c) / whole, wc = cross(a, b, p) / whole;
  if (wa < -kTolerance || wb < -kTolerance || wc < -kTolerance) return false;
  h = wa * lengths_[t.v[0]] + wb * lengths_[t.v[1]] + wc * lengths_[t.v[2]];
  return true;
}

double SizeField::nearest_vertex_length(const Point& p) const {
  double best = HUGE_VAL, h = lengths_.empty() ? HUGE_VAL : lengths_[0];
  for (std::size_t v = 0; v < points_.size(); ++v) {
    const double dx = points_[v].x - p.x, dy = points_[v].y - p.y, d = dx * dx + dy * dy;
    if (d < best) best = d, h = lengths_[v];
  }
  return h;
}

double SizeField::length_at(const Point& p) const {
  if (!triangles_.empty() && p.x >= lo_x_ - cell_size_ && p.y >= lo_y_ - cell_size_) {
    const std::size_t cell = cell_of(p.x, p.y);
    // Where p lies on a side shared by several triangles, the smallest of their values (to rounding, one value).
    double smallest = HUGE_VAL, h = 0.0;
    for (std::uint32_t i = cell_start_[cell]; i < cell_start_[cell + 1]; ++i)
      if (interpolate(triangles_[cell_list_[i]], p, h)) smallest = std::min(smallest, h);
    if (smallest < HUGE_VAL) return smallest;
  }
  return nearest_vertex_length(p);
}

SizeTest SizeField::test() const {
  return [this](const Point& a, const Point& b, const Point& c, double area) {
    const double h = length_at({(a.x + b.x + c.x) / 3.0, (a.y + b.y + c.y) / 3.0});
    return area > kEquilateralArea * h * h;
  };
}

}  // namespace deltri
