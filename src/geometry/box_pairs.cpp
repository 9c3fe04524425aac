#include "geometry/box_pairs.h"

#include <algorithm>
#include <cmath>

namespace deltri {

std::uint32_t grid_index(double v, long double origin, long double size, std::uint32_t count) {
  const long double k = (static_cast<long double>(v) - origin) / size;
  if (!(k > 0)) return 0;
  return k >= count ? count - 1 : static_cast<std::uint32_t>(k);
}

BoxPairs::BoxPairs(std::vector<Box> boxes) : boxes_(std::move(boxes)) {
  if (boxes_.size() < 2) return;  // no pairs: cell_start_ stays empty
  make_grid();
  fill_cells();
}

void BoxPairs::make_grid() {
  Box all = boxes_[0];
  for (const Box& b : boxes_) {
    all.lo_x = std::min(all.lo_x, b.lo_x), all.hi_x = std::max(all.hi_x, b.hi_x);
    all.lo_y = std::min(all.lo_y, b.lo_y), all.hi_y = std::max(all.hi_y, b.hi_y);
  }
  // About two cells per box, shaped like the union.
  const long double span_x = static_cast<long double>(all.hi_x) - all.lo_x;
  const long double span_y = static_cast<long double>(all.hi_y) - all.lo_y;
  const long double cells = 2.0L * static_cast<long double>(boxes_.size());
  long double aspect = span_y > 0 && span_x > 0 ? span_x / span_y : 1.0L;
  aspect = std::clamp(aspect, 1.0L / cells, cells);
  columns_ = static_cast<std::uint32_t>(std::clamp(std::sqrt(cells * aspect), 1.0L, cells));
  rows_ = static_cast<std::uint32_t>(std::clamp(cells / columns_, 1.0L, cells));
  x0_ = all.lo_x, y0_ = all.lo_y;
  const long double w = span_x / columns_, h = span_y / rows_;
  cell_w_ = w > 0 ? w : 1, cell_h_ = h > 0 ? h : 1;
}

// Boxes in the order of their lower-left cells, so that a cell's boxes sit together in memory
// (in the caller's order they are scattered, and the pair loop would wait on cache misses).
void BoxPairs::sort_by_home_cell() {
  const auto home = [&](const CellRange& r) { return static_cast<std::size_t>(r.r0) * columns_ + r.c0; };
  std::vector<std::uint32_t> order(ranges_.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k;
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return home(ranges_[a]) < home(ranges_[b]); });
  std::vector<Box> boxes(order.size());
  std::vector<CellRange> ranges(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) boxes[k] = boxes_[order[k]], ranges[k] = ranges_[order[k]];
  boxes_.swap(boxes), ranges_.swap(ranges), item_.swap(order);
}

// Counting sort of (cell, box) pairs into cell_start_ / in_cell_.
void BoxPairs::fill_cells() {
  ranges_.reserve(boxes_.size());
  for (const Box& b : boxes_)
    ranges_.push_back({grid_index(b.lo_x, x0_, cell_w_, columns_), grid_index(b.hi_x, x0_, cell_w_, columns_),
                       grid_index(b.lo_y, y0_, cell_h_, rows_), grid_index(b.hi_y, y0_, cell_h_, rows_)});
  sort_by_home_cell();
  cell_start_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  for (const CellRange& b : ranges_) for_cells(b, [&](std::uint32_t c) { ++cell_start_[c + 1]; });
  for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
  in_cell_.resize(cell_start_.back());
  std::vector<std::size_t> next(cell_start_.begin(), cell_start_.end() - 1);
  for (std::uint32_t k = 0; k < ranges_.size(); ++k) for_cells(ranges_[k], [&](std::uint32_t c) { in_cell_[next[c]++] = k; });
}

// The cell's boxes that start in it, that start in its row only, and in its column only.
void BoxPairs::sort_cell(std::uint32_t c) {
  const std::uint32_t row = c / columns_, column = c % columns_;
  corner_here_.clear(), row_here_.clear(), column_here_.clear();
  for (std::size_t i = cell_start_[c]; i < cell_start_[c + 1]; ++i) {
    const std::uint32_t k = in_cell_[i];
    const bool starts_row = ranges_[k].r0 == row, starts_column = ranges_[k].c0 == column;
    if (starts_row && starts_column) corner_here_.push_back(k);
    else if (starts_row) row_here_.push_back(k);
    else if (starts_column) column_here_.push_back(k);
  }
}

bool BoxPairs::meet(std::uint32_t p, std::uint32_t q) const {
  const Box &a = boxes_[p], &b = boxes_[q];
  return std::max(a.lo_x, b.lo_x) <= std::min(a.hi_x, b.hi_x) && std::max(a.lo_y, b.lo_y) <= std::min(a.hi_y, b.hi_y);
}

}  // namespace deltri
