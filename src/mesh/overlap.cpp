#include "mesh/overlap.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace deltri {
namespace {

struct Box {
  double lo_x, lo_y, hi_x, hi_y;
};

struct CellRange {
  std::uint32_t c0, c1, r0, r1;
};

struct Grid {
  long double x0 = 0, y0 = 0, cell_w = 1, cell_h = 1;  // long double: no overflow of the spans
  std::uint32_t columns = 1, rows = 1;

  std::uint32_t column(double x) const { return index(x, x0, cell_w, columns); }
  std::uint32_t row(double y) const { return index(y, y0, cell_h, rows); }

  static std::uint32_t index(double v, long double origin, long double size, std::uint32_t count) {
    const long double k = (static_cast<long double>(v) - origin) / size;
    if (!(k > 0)) return 0;
    return k >= count ? count - 1 : static_cast<std::uint32_t>(k);
  }
};

class OverlapFinder {
 public:
  OverlapFinder(const Mesh& mesh, Predicates& pred) : mesh_(mesh), pred_(pred) {}

  std::optional<OverlapFinding> run() {
    for (TriangleId t{0}; t < mesh_.triangle_slots(); ++t)
      if (mesh_.is_live(t)) live_.push_back(t);
    if (live_.size() < 2) return std::nullopt;
    boxes_.reserve(live_.size());
    for (const TriangleId t : live_) boxes_.push_back(box_of(t));
    make_grid();
    fill_cells();
    for (std::uint32_t c = 0; c + 1 < cell_start_.size(); ++c)
      if (auto found = scan_cell(c)) return found;
    return std::nullopt;
  }

 private:
  const Point& corner(TriangleId t, unsigned i) const { return mesh_.point(mesh_.corner[edge_of(t, i)]); }

  Box box_of(TriangleId t) const {
    Box b{corner(t, 0).x, corner(t, 0).y, corner(t, 0).x, corner(t, 0).y};
    for (unsigned i = 1; i < 3; ++i) {
      b.lo_x = std::min(b.lo_x, corner(t, i).x), b.hi_x = std::max(b.hi_x, corner(t, i).x);
      b.lo_y = std::min(b.lo_y, corner(t, i).y), b.hi_y = std::max(b.hi_y, corner(t, i).y);
    }
    return b;
  }

  void make_grid() {
    Box all = boxes_[0];
    for (const Box& b : boxes_) {
      all.lo_x = std::min(all.lo_x, b.lo_x), all.hi_x = std::max(all.hi_x, b.hi_x);
      all.lo_y = std::min(all.lo_y, b.lo_y), all.hi_y = std::max(all.hi_y, b.hi_y);
    }
    // About two cells per triangle, shaped like the bounding box.
    const long double span_x = static_cast<long double>(all.hi_x) - all.lo_x;
    const long double span_y = static_cast<long double>(all.hi_y) - all.lo_y;
    const long double cells = 2.0L * static_cast<long double>(live_.size());
    long double aspect = span_y > 0 && span_x > 0 ? span_x / span_y : 1.0L;
    aspect = std::clamp(aspect, 1.0L / cells, cells);
    grid_.columns = static_cast<std::uint32_t>(std::clamp(std::sqrt(cells * aspect), 1.0L, cells));
    grid_.rows = static_cast<std::uint32_t>(std::clamp(cells / grid_.columns, 1.0L, cells));
    grid_.x0 = all.lo_x, grid_.y0 = all.lo_y;
    const long double w = span_x / grid_.columns, h = span_y / grid_.rows;
    grid_.cell_w = w > 0 ? w : 1, grid_.cell_h = h > 0 ? h : 1;
  }

  template <class F>
  void for_cells(const CellRange& b, F&& f) const {
    for (std::uint32_t r = b.r0; r <= b.r1; ++r)
      for (std::uint32_t c = b.c0; c <= b.c1; ++c) f(r * grid_.columns + c);
  }

  // Triangles in the order of their lower-left cells, so that a cell's triangles sit together in
  // memory (in file order they are scattered, and the pair loop would wait on cache misses).
  void sort_by_home_cell() {
    const auto home = [&](const CellRange& r) { return static_cast<std::size_t>(r.r0) * grid_.columns + r.c0; };
    std::vector<std::uint32_t> order(ranges_.size());
    for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k;
    std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return home(ranges_[a]) < home(ranges_[b]); });
    std::vector<TriangleId> live(order.size());
    std::vector<Box> boxes(order.size());
    std::vector<CellRange> ranges(order.size());
    for (std::size_t k = 0; k < order.size(); ++k)
      live[k] = live_[order[k]], boxes[k] = boxes_[order[k]], ranges[k] = ranges_[order[k]];
    live_.swap(live), boxes_.swap(boxes), ranges_.swap(ranges);
  }

  // Counting sort of (cell, triangle) pairs into cell_start_ / in_cell_.
  void fill_cells() {
    ranges_.reserve(boxes_.size());
    for (const Box& b : boxes_)
      ranges_.push_back({grid_.column(b.lo_x), grid_.column(b.hi_x), grid_.row(b.lo_y), grid_.row(b.hi_y)});
    sort_by_home_cell();
    cell_start_.assign(static_cast<std::size_t>(grid_.columns) * grid_.rows + 1, 0);
    for (const CellRange& b : ranges_) for_cells(b, [&](std::uint32_t c) { ++cell_start_[c + 1]; });
    for (std::size_t c = 1; c < cell_start_.size(); ++c) cell_start_[c] += cell_start_[c - 1];
    in_cell_.resize(cell_start_.back());
    std::vector<std::size_t> next(cell_start_.begin(), cell_start_.end() - 1);
    for (std::uint32_t k = 0; k < ranges_.size(); ++k) for_cells(ranges_[k], [&](std::uint32_t c) { in_cell_[next[c]++] = k; });
  }

  // A pair is tested in the cell of its boxes' intersection's lower-left corner: the larger of
  // their first rows and the larger of their first columns, so at least one of the two starts in
  // this row and one (the same or the other) in this column. Only such pairs are enumerated: each
  // triangle starting here against all the cell's triangles, and those starting in this row only
  // against those starting in this column only. Trying every pair of every cell would visit a pair
  // once per shared cell, which made long slivers (a fan, a crowded crossing) cubic.
  std::optional<OverlapFinding> scan_cell(std::uint32_t c) {
    const std::uint32_t row = c / grid_.columns, column = c % grid_.columns;
    corner_here_.clear(), row_here_.clear(), column_here_.clear();
    for (std::size_t i = cell_start_[c]; i < cell_start_[c + 1]; ++i) {
      const std::uint32_t k = in_cell_[i];
      const bool starts_row = ranges_[k].r0 == row, starts_column = ranges_[k].c0 == column;
      if (starts_row && starts_column) corner_here_.push_back(k);
      else if (starts_row) row_here_.push_back(k);
      else if (starts_column) column_here_.push_back(k);
    }
    for (std::size_t i = 0; i < corner_here_.size(); ++i) {
      const std::uint32_t p = corner_here_[i];
      for (std::size_t j = cell_start_[c]; j < cell_start_[c + 1]; ++j) {
        const std::uint32_t q = in_cell_[j];
        const bool q_corner_here = ranges_[q].r0 == row && ranges_[q].c0 == column;
        if (q == p || (q_corner_here && q < p)) continue;  // a pair of two starting here: once
        if (auto found = test_if_boxes_meet(p, q)) return found;
      }
    }
    for (const std::uint32_t p : row_here_)
      for (const std::uint32_t q : column_here_)
        if (auto found = test_if_boxes_meet(p, q)) return found;
    return std::nullopt;
  }

  std::optional<OverlapFinding> test_if_boxes_meet(std::uint32_t p, std::uint32_t q) {
    const Box &a = boxes_[p], &b = boxes_[q];
    if (std::max(a.lo_x, b.lo_x) > std::min(a.hi_x, b.hi_x) || std::max(a.lo_y, b.lo_y) > std::min(a.hi_y, b.hi_y))
      return std::nullopt;
    return test(std::min(live_[p], live_[q]), std::max(live_[p], live_[q]));
  }

  bool is_corner(VertexId v, TriangleId t) const {
    return mesh_.corner[edge_of(t, 0)] == v || mesh_.corner[edge_of(t, 1)] == v || mesh_.corner[edge_of(t, 2)] == v;
  }

  // An edge line of `t` with all of u's corners on its closed outer (right) side.
  bool separates(TriangleId t, TriangleId u) {
    for (unsigned i = 0; i < 3; ++i) {
      const Point &a = corner(t, i), &b = corner(t, (i + 1) % 3);
      if (pred_.orient2d(a, b, corner(u, 0)) <= 0 && pred_.orient2d(a, b, corner(u, 1)) <= 0 &&
          pred_.orient2d(a, b, corner(u, 2)) <= 0)
        return true;
    }
    return false;
  }

  // A corner of u, not a corner of t, in the closed triangle t.
  bool corner_on(TriangleId t, TriangleId u) {
    for (unsigned i = 0; i < 3; ++i) {
      const VertexId v = mesh_.corner[edge_of(u, i)];
      if (is_corner(v, t)) continue;
      const Point& p = mesh_.point(v);
      if (pred_.orient2d(corner(t, 0), corner(t, 1), p) >= 0 && pred_.orient2d(corner(t, 1), corner(t, 2), p) >= 0 &&
          pred_.orient2d(corner(t, 2), corner(t, 0), p) >= 0)
        return true;
    }
    return false;
  }

  std::optional<OverlapFinding> test(TriangleId t, TriangleId u) {
    // Two corners in common: an edge shared in opposite directions (the same direction is a
    // repeated directed edge, rejected before), so the two lie on opposite sides of it.
    int shared = 0;
    for (unsigned i = 0; i < 3; ++i) shared += is_corner(mesh_.corner[edge_of(u, i)], t);
    if (shared >= 2) return std::nullopt;
    if (!separates(t, u) && !separates(u, t)) return OverlapFinding{t, u, true};
    if (corner_on(t, u) || corner_on(u, t)) return OverlapFinding{t, u, false};
    return std::nullopt;
  }

  const Mesh& mesh_;
  Predicates& pred_;
  std::vector<TriangleId> live_;
  std::vector<Box> boxes_;
  std::vector<CellRange> ranges_;
  Grid grid_;
  std::vector<std::size_t> cell_start_;
  std::vector<std::uint32_t> in_cell_;
  std::vector<std::uint32_t> corner_here_, row_here_, column_here_;  // scratch of scan_cell
};

}  // namespace

std::optional<OverlapFinding> find_overlap(const Mesh& mesh, Predicates& pred) {
  return OverlapFinder(mesh, pred).run();
}

}  // namespace deltri
