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
  std::vector<Box> boxes(triangles_.size());
  Box all;
  for (std::size_t k = 0; k < triangles_.size(); ++k)
    for (std::uint32_t v : triangles_[k].v) boxes[k].add(points_[v]), all.add(points_[v]);
  const double width = std::max(all.width(), 1e-300), height = std::max(all.height(), 1e-300);
  const double cell = std::max(std::sqrt(width * height / static_cast<double>(triangles_.size())), std::max(width, height) / 4096.0);
  grid_ = TriangleGrid(boxes, all, cell);
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
  if (!triangles_.empty() && p.x >= grid_.lo_x() - grid_.cell_size() && p.y >= grid_.lo_y() - grid_.cell_size()) {
    // Where p lies on a side shared by several triangles, the smallest of their values (to rounding, one value).
    double smallest = HUGE_VAL, h = 0.0;
    for (std::uint32_t i : grid_.near(p))
      if (interpolate(triangles_[i], p, h)) smallest = std::min(smallest, h);
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
