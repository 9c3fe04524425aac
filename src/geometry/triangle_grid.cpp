#include "geometry/triangle_grid.h"

#include <algorithm>

namespace deltri {

TriangleGrid::TriangleGrid(const std::vector<Box>& boxes, const Box& all, double cell)
    : lo_x_(all.lo_x), lo_y_(all.lo_y), cell_size_(cell) {
  columns_ = static_cast<std::size_t>(all.width() / cell_size_) + 1;
  rows_ = static_cast<std::size_t>(all.height() / cell_size_) + 1;
  // Two passes over the boxes: count per cell, then fill.
  std::vector<std::uint32_t> count(columns_ * rows_ + 1, 0);
  const auto each_cell = [&](const Box& b, auto&& visit) {
    const std::size_t c0 = cell_of(b.lo_x, b.lo_y), c1 = cell_of(b.hi_x, b.hi_y);
    for (std::size_t row = c0 / columns_; row <= c1 / columns_; ++row)
      for (std::size_t col = c0 % columns_; col <= c1 % columns_; ++col) visit(row * columns_ + col);
  };
  for (const Box& b : boxes) each_cell(b, [&](std::size_t c) { ++count[c + 1]; });
  for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  cell_start_ = count;
  cell_list_.resize(count.back());
  for (std::uint32_t i = 0; i < boxes.size(); ++i) each_cell(boxes[i], [&](std::size_t c) { cell_list_[count[c]++] = i; });
}

std::size_t TriangleGrid::cell_of(double x, double y) const {
  const auto clamp = [](double v, std::size_t n) {
    return static_cast<std::size_t>(std::clamp(v, 0.0, static_cast<double>(n - 1)));
  };
  return clamp((y - lo_y_) / cell_size_, rows_) * columns_ + clamp((x - lo_x_) / cell_size_, columns_);
}

std::span<const std::uint32_t> TriangleGrid::near(const Point& p) const {
  if (cell_start_.empty()) return {};
  const std::size_t c = cell_of(p.x, p.y);
  return {cell_list_.data() + cell_start_[c], cell_list_.data() + cell_start_[c + 1]};
}

}  // namespace deltri
