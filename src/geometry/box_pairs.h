// The pairs of boxes that meet, each visited once, for exact tests that only such pairs can need
// (mesh/overlap.cpp: triangles; mesh/embedding.cpp: boundary edges).
//
// The boxes are bucketed on a uniform grid of about two cells per box, shaped like their union. A
// pair is visited in the cell of the lower-left corner of the boxes' intersection: the larger of
// their first rows and the larger of their first columns, so at least one of the two starts in
// this row and one (the same or the other) in this column. Only such pairs are enumerated: each
// box starting in the cell against all the cell's boxes, and those starting in its row only
// against those starting in its column only. Trying every pair of every cell would visit a pair
// once per shared cell, which made long slivers (a fan, a crowded crossing) cubic. The work is
// linear when the boxes are of similar size, and the number of meeting pairs at worst (quadratic
// when long thin boxes cross many others).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "geometry/box.h"

namespace deltri {

// The index of the cell holding v, for `count` cells of `size` from `origin`, clamped to the grid.
// long double: the spans of extreme coordinates do not overflow. Monotone in v.
std::uint32_t grid_index(double v, long double origin, long double size, std::uint32_t count);

class BoxPairs {
 public:
  explicit BoxPairs(std::vector<Box> boxes);

  // Calls visit(i, j), i and j indices into the boxes given, once for each pair of boxes that
  // meet (closed boxes), in an order fixed by the boxes alone, until a call returns true; returns
  // whether one did.
  template <class Visit>
  bool any(Visit&& visit) {
    for (std::uint32_t c = 0; c + 1 < cell_start_.size(); ++c)
      if (scan_cell(c, visit)) return true;
    return false;
  }

 private:
  struct CellRange {
    std::uint32_t c0, c1, r0, r1;
  };

  void make_grid();
  void sort_by_home_cell();
  void fill_cells();
  void sort_cell(std::uint32_t c);
  bool meet(std::uint32_t p, std::uint32_t q) const;

  template <class F>
  void for_cells(const CellRange& b, F&& f) const {
    for (std::uint32_t r = b.r0; r <= b.r1; ++r)
      for (std::uint32_t c = b.c0; c <= b.c1; ++c) f(r * columns_ + c);
  }

  template <class Visit>
  bool scan_cell(std::uint32_t c, Visit& visit) {
    sort_cell(c);
    const std::uint32_t row = c / columns_, column = c % columns_;
    const bool apart = corner_here_.size() > kCrowded && corner_here_.size() < boxes_.size();
    if (apart && pairs_among_corner_here(visit)) return true;
    for (const std::uint32_t p : corner_here_) {
      for (std::size_t j = cell_start_[c]; j < cell_start_[c + 1]; ++j) {
        const std::uint32_t q = in_cell_[j];
        const bool q_corner_here = ranges_[q].r0 == row && ranges_[q].c0 == column;
        if (q == p || (q_corner_here && (apart || q < p))) continue;  // a pair of two starting here: once
        if (meet(p, q) && visit(item_[p], item_[q])) return true;
      }
    }
    for (const std::uint32_t p : row_here_)
      for (const std::uint32_t q : column_here_)
        if (meet(p, q) && visit(item_[p], item_[q])) return true;
    return false;
  }

  // A graded mesh (refinement towards a small input angle) puts thousands of small boxes in one
  // cell of a grid sized for the average box, and testing them pair by pair there was quadratic
  // (Chew's algorithm on debug2.poly: minutes). The pairs of boxes that start in such a cell are
  // found by a BoxPairs of their own, whose grid fits them; each pair is still visited once.
  static constexpr std::size_t kCrowded = 64;
  template <class Visit>
  bool pairs_among_corner_here(Visit& visit) {
    std::vector<Box> some;
    some.reserve(corner_here_.size());
    for (const std::uint32_t p : corner_here_) some.push_back(boxes_[p]);
    auto mapped = [&](std::uint32_t i, std::uint32_t j) { return visit(item_[corner_here_[i]], item_[corner_here_[j]]); };
    return BoxPairs(std::move(some)).any(PairVisitor::of(mapped));
  }
  // One visitor type for every nested level, so that the nesting does not instantiate the
  // templates anew for each level's lambda (without end).
  struct PairVisitor {
    void* context;
    bool (*call)(void*, std::uint32_t, std::uint32_t);
    bool operator()(std::uint32_t i, std::uint32_t j) const { return call(context, i, j); }
    template <class F>
    static PairVisitor of(F& f) {
      return {&f, [](void* c, std::uint32_t i, std::uint32_t j) { return (*static_cast<F*>(c))(i, j); }};
    }
  };

  // Sorted by home cell (so that a cell's boxes sit together in memory); item_ maps back.
  std::vector<Box> boxes_;
  std::vector<std::uint32_t> item_;
  std::vector<CellRange> ranges_;
  long double x0_ = 0, y0_ = 0, cell_w_ = 1, cell_h_ = 1;
  std::uint32_t columns_ = 1, rows_ = 1;
  std::vector<std::size_t> cell_start_;
  std::vector<std::uint32_t> in_cell_;
  std::vector<std::uint32_t> corner_here_, row_here_, column_here_;  // scratch of scan_cell
};

}  // namespace deltri
